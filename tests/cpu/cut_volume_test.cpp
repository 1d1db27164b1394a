// Cut volumes (src/volumes/): specs and their JSON list parse to the same volumes, bad ones are
// refused with a message naming the field, and every kind builds a closed mesh enclosing what
// it says.
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "mesh_checks.h"
#include "test_files.h"
#include "volumes/cut_volume_json.h"
#include "volumes/cut_volume_spec.h"
#include "volumes/mesh_file.h"
#include "volumes/volume_mesh.h"

namespace cutaway::volumes {
namespace {

/// The message `call` throws as std::invalid_argument ("" if it does not throw).
template <typename Call>
std::string refusal(Call call) {
    try {
        call();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// A unit cube as OBJ faces (quads, wound outward unless `inward`); `faces` of the six kept.
std::string cube_obj(int faces = 6, bool inward = false) {
    std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    const char* outward[6] = {"f 1 4 3 2\n", "f 5 6 7 8\n", "f 1 2 6 5\n", "f 2 3 7 6\n", "f 3 4 8 7\n", "f 4 1 5 8\n"};
    const char* reversed[6] = {"f 2 3 4 1\n", "f 8 7 6 5\n", "f 5 6 2 1\n", "f 6 7 3 2\n", "f 7 8 4 3\n", "f 8 5 1 4\n"};
    for (int f = 0; f < faces; ++f) text += inward ? reversed[f] : outward[f];
    return text;
}

const VolumeBuildContext no_wells{nullptr, 1.0, std::size_t(1) << 30};

TEST(CutVolumeSpec, EachKindParses) {
    const CutVolume box = parse_cut_volume_spec("box:10,20,30,0,0,0");
    ASSERT_TRUE(std::holds_alternative<BoxVolume>(box));
    EXPECT_EQ(std::get<BoxVolume>(box).min.x, 0);  // corners in any order
    EXPECT_EQ(std::get<BoxVolume>(box).max.z, 30);
    const auto cylinder = std::get<CylinderVolume>(parse_cut_volume_spec("cylinder:0,0,0,0,0,100,2.5"));
    EXPECT_EQ(cylinder.radius, 2.5);
    const auto well = std::get<WellVolume>(parse_cut_volume_spec("well:PROD1"));
    EXPECT_EQ(well.name, "PROD1");
    EXPECT_FALSE(well.radius.has_value());
    EXPECT_EQ(std::get<WellVolume>(parse_cut_volume_spec("well:I1,30")).radius, 30.0);
    EXPECT_EQ(std::get<MeshVolume>(parse_cut_volume_spec("mesh:salt dome.ply")).file, "salt dome.ply");
}

TEST(CutVolumeSpec, SpecTextParsesBackToTheSameNumbers) {
    for (const char* spec : {"box:0.1,0.2,0.3,1e5,2e5,3000.125", "cylinder:1,2,3,4,5,6,0.7", "well:W,12.5", "well:W", "mesh:a.obj"}) {
        const CutVolume volume = parse_cut_volume_spec(spec);
        EXPECT_EQ(spec_text(parse_cut_volume_spec(spec_text(volume))), spec_text(volume)) << spec;
    }
    EXPECT_EQ(spec_text(parse_cut_volume_spec("box:0,0,0,1,2,3")), "box:0,0,0,1,2,3");
}

TEST(CutVolumeSpec, RefusesBadSpecsNamingTheField) {
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("box"); }), "expected KIND:VALUES"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("sphere:1,2,3"); }), "expected one of box:"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("box:1,2,3"); }), "expected 6 numbers"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("box:1,2,x,4,5,6"); }), "box number 3"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("box:0,0,0,1,0,1"); }), "zero extent along y"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("box:0,0,0,1,1,inf"); }), "finite number"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("cylinder:0,0,0,0,0,1,0"); }), "cylinder radius"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("cylinder:0,0,0,0,0,1,-2"); }), "radius > 0"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("cylinder:1,1,1,1,1,1,2"); }), "zero length"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("well:"); }), "well name"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("well:P1,0"); }), "well radius"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("mesh:"); }), "file name"));
    EXPECT_TRUE(contains(refusal([] { parse_cut_volume_spec("box:1,2,3"); }), "--cut-volume 'box:1,2,3'"));
}

TEST(CutVolumeJson, SameVolumesAsTheSpecs) {
    const std::string text = R"({"volumes": [
        {"kind": "box", "min": [0.1, 0.2, 0.3], "max": [4, 5, 6]},
        {"kind": "cylinder", "from": [1, 2, 3], "to": [4, 5, 6], "radius": 0.7},
        {"kind": "well", "name": "P1", "radius": 20},
        {"kind": "well", "name": "P2"},
        {"kind": "mesh", "file": "salt.ply"},
        {"kind": "mesh", "file": "/abs/x.obj"}]})";
    const std::vector<CutVolume> volumes = parse_cut_volumes_json(text, "/data/cuts", "v.json");
    const std::vector<std::string> specs = {"box:0.1,0.2,0.3,4,5,6", "cylinder:1,2,3,4,5,6,0.7", "well:P1,20", "well:P2",
                                            "mesh:/data/cuts/salt.ply", "mesh:/abs/x.obj"};
    ASSERT_EQ(volumes.size(), specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i) EXPECT_EQ(spec_text(volumes[i]), spec_text(parse_cut_volume_spec(specs[i])));
    // The document written back reads as the same list.
    const std::vector<CutVolume> again = parse_cut_volumes_json(cut_volumes_document(volumes).dump(), "/elsewhere", "w.json");
    for (std::size_t i = 0; i < specs.size(); ++i) EXPECT_EQ(spec_text(again[i]), spec_text(volumes[i]));
}

TEST(CutVolumeJson, RefusesBadDocumentsNamingTheEntryAndField) {
    const auto parse = [](const std::string& text) { return refusal([&] { parse_cut_volumes_json(text, ".", "v.json"); }); };
    EXPECT_TRUE(contains(parse("{\"volumes\": ["), "syntax error"));
    EXPECT_TRUE(contains(parse("[]"), "expected {\"volumes\": [...]}"));
    EXPECT_TRUE(contains(parse(R"({"volumes": [], "extra": 1})"), "extra: not a field"));
    EXPECT_TRUE(contains(parse(R"({"volumes": [{"min": [0,0,0]}]})"), "volumes[0].kind: missing"));
    EXPECT_TRUE(contains(parse(R"({"volumes": [{"kind": "cone"}]})"), "volumes[0].kind: expected box"));
    EXPECT_TRUE(contains(parse(R"({"volumes": [{"kind": "box", "min": [0,0], "max": [1,1,1]}]})"), "volumes[0].min: expected [X, Y, Z]"));
    EXPECT_TRUE(contains(parse(R"({"volumes": [{"kind": "box", "min": [0,0,0], "max": [1,1,0]}]})"), "volumes[0]: box: zero extent along z"));
    EXPECT_TRUE(contains(parse(R"({"volumes": [{"kind": "box", "min": [0,0,0], "max": [1,1,1], "radius": 2}]})"), "volumes[0].radius: not a field"));
    EXPECT_TRUE(contains(parse(R"({"volumes": [{"kind": "cylinder", "from": [0,0,0], "to": [1,1,1], "radius": "2"}]})"), "volumes[0].radius: expected a number"));
    EXPECT_TRUE(contains(parse(R"({"volumes": [{"kind": "well", "name": "A"}, {"kind": "well", "name": "B", "radius": 0}]})"), "volumes[1]: well radius"));
}

TEST(CutVolumeJson, ReadsAFileAndItsMeshesRelativeToIt) {
    const test::ScratchDir dir("cut-volume-json");
    const auto file = dir.write("v.json", R"({"volumes": [{"kind": "mesh", "file": "cube.obj"}]})");
    const std::vector<CutVolume> volumes = read_cut_volumes_file(file.string(), std::size_t(1) << 30);
    EXPECT_EQ(std::get<MeshVolume>(volumes.at(0)).file, (dir.path() / "cube.obj").string());
    EXPECT_TRUE(contains(refusal([&] { read_cut_volumes_file((dir.path() / "none.json").string(), 1 << 30); }), "expected a readable JSON file"));
    EXPECT_TRUE(contains(refusal([&] { read_cut_volumes_file(file.string(), 100); }), "--memory-limit-gb"));
}

TEST(VolumeMesh, BoxIsClosedAndEnclosesItsVolume) {
    const shapes::TriangleMesh box = build_volume_mesh(parse_cut_volume_spec("box:1,2,3,4,6,8"), no_wells);
    EXPECT_EQ(box.triangles.size(), 12u);
    EXPECT_TRUE(shapes::closed_and_consistent(box));
    EXPECT_NEAR(shapes::enclosed_volume(box), 3.0 * 4.0 * 5.0, 1e-12);  // exact corners: only rounding
    for (std::size_t i = 0; i < box.positions.size(); ++i) {  // normals point away from the centre
        const grid::Point3 &p = box.positions[i], &n = box.normals[i];
        EXPECT_GT((p.x - 2.5) * n.x + (p.y - 4) * n.y + (p.z - 5.5) * n.z, 0) << i;
    }
}

TEST(VolumeMesh, CylinderIsTheInscribedPrism) {
    const shapes::TriangleMesh c = build_volume_mesh(parse_cut_volume_spec("cylinder:0,0,0,0,0,10,2"), no_wells);
    EXPECT_TRUE(shapes::closed_and_consistent(c));
    const double area = 0.5 * tube_sides * 4.0 * std::sin(2 * std::acos(-1.0) / tube_sides);
    EXPECT_NEAR(shapes::enclosed_volume(c), area * 10, 1e-9 * area * 10);
}

TEST(VolumeMesh, WellsResolveThroughTheCallersPaths) {
    EXPECT_EQ(refusal([] { build_volume_mesh(parse_cut_volume_spec("well:P1"), no_wells); }),
              "--cut-volume 'well:P1': unknown well P1 (the model has no wells)");
    const WellPaths wells{{"INJ", {{0, 0, 0}, {0, 0, 50}, {30, 0, 60}}}, {"PROD", {{100, 0, 0}, {100, 0, 50}}}};
    const VolumeBuildContext context{&wells, 5.0, std::size_t(1) << 30};
    EXPECT_TRUE(contains(refusal([&] { build_volume_mesh(parse_cut_volume_spec("well:P1"), context); }),
                         "unknown well P1 (the model's wells: INJ, PROD)"));
    const shapes::TriangleMesh tube = build_volume_mesh(parse_cut_volume_spec("well:PROD"), context);
    EXPECT_TRUE(shapes::closed_and_consistent(tube));
    EXPECT_NEAR(shapes::bounds(tube).max.x, 105, 1e-9);  // the default radius
    EXPECT_NEAR(shapes::bounds(build_volume_mesh(parse_cut_volume_spec("well:PROD,2"), context)).max.x, 102, 1e-9);
}

TEST(MeshFile, ReadsAClosedMeshTriangulatedAndWoundOutward) {
    const test::ScratchDir dir("mesh-file");
    // Wound inward on purpose: the reader turns it outward.
    const shapes::TriangleMesh cube = read_closed_mesh(dir.write("cube.obj", cube_obj(6, true)).string(), std::size_t(1) << 30);
    EXPECT_EQ(cube.triangles.size(), 12u);
    EXPECT_TRUE(shapes::closed_and_consistent(cube));
    EXPECT_NEAR(shapes::enclosed_volume(cube), 1.0, 1e-12);
    const std::string ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                            "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    const shapes::TriangleMesh tetrahedron = read_closed_mesh(dir.write("t.PLY", ply).string(), std::size_t(1) << 30);
    EXPECT_NEAR(shapes::enclosed_volume(tetrahedron), 1.0 / 6, 1e-7);  // float coordinates in the file
}

TEST(MeshFile, RefusesOpenNonManifoldMissingAndOversizedMeshes) {
    const test::ScratchDir dir("mesh-file-bad");
    const std::size_t plenty = std::size_t(1) << 30;
    EXPECT_TRUE(contains(refusal([&] { read_closed_mesh(dir.write("open.obj", cube_obj(5)).string(), plenty); }), "expected a closed mesh"));
    // Two cubes sharing one edge: four faces meet on it.
    std::string two = cube_obj();
    two += "v 2 2 0\nv 2 1 0\nv 2 2 1\nv 2 1 1\nv 1 2 0\nv 1 2 1\n";
    two += "f 3 13 9 10\nf 7 12 11 14\nf 3 10 12 7\nf 10 9 11 12\nf 9 13 14 11\nf 13 3 7 14\n";
    EXPECT_TRUE(contains(refusal([&] { read_closed_mesh(dir.write("two.obj", two).string(), plenty); }), "non-manifold"));
    EXPECT_TRUE(contains(refusal([&] { read_closed_mesh((dir.path() / "none.ply").string(), plenty); }), "expected a readable mesh file"));
    EXPECT_TRUE(contains(refusal([&] { read_closed_mesh(dir.write("c.stl", "solid").string(), plenty); }), "expected a .ply or .obj"));
    const auto cube = dir.write("cube.obj", cube_obj());
    EXPECT_TRUE(contains(refusal([&] { read_closed_mesh(cube.string(), std::filesystem::file_size(cube) * mesh_bytes_per_file_byte - 1); }),
                         "--memory-limit-gb"));
}

}  // namespace
}  // namespace cutaway::volumes
