// Bad cut volumes (issue 45), as a user meets them: malformed or degenerate specs are refused
// while the options are parsed (no GL, before the model is read); unknown wells, bad mesh files
// and bad JSON lists once the model is known. Each is one line naming the spec, file or field,
// exit 2, nothing written.
#include <gtest/gtest.h>

#include <string>

#include "bad_input_fixture.h"

namespace {

using namespace cutaway::testing;
namespace fs = std::filesystem;

/// A unit cube in OBJ, `faces` of its six quads kept (wound outward).
std::string cube_obj(int faces = 6) {
    std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    const char* quads[6] = {"f 1 4 3 2\n", "f 5 6 7 8\n", "f 1 2 6 5\n", "f 2 3 7 6\n", "f 3 4 8 7\n", "f 4 1 5 8\n"};
    for (int f = 0; f < faces; ++f) text += quads[f];
    return text;
}

TEST_F(BadInput, MalformedAndDegenerateCutVolumesAreRefusedWhileParsing) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const auto refused = [&](const std::string& spec, const std::vector<std::string>& fragments) {
        std::vector<std::string> expected = fragments;
        expected.push_back("--cut-volume");
        expected.push_back(spec);
        const ProcessResult r = cutaway({"render", grid.string(), "--cut-volume", spec, "--out", out("x.png")});
        expect_refused(r, expected);
        EXPECT_LT(r.seconds, 5) << spec << " refused only after rendering";
    };
    refused("box:1,2", {"expected 6 numbers X0,Y0,Z0,X1,Y1,Z1, found 2"});
    refused("box:0,0,0,1,1,z", {"box number 6", "expected a finite number, found 'z'"});
    refused("sphere:0,0,0,1", {"expected one of box:"});
    refused("box0,0,0,1,1,1", {"expected KIND:VALUES"});
    refused("box:0,0,0,1,0,1", {"zero extent along y"});
    refused("cylinder:0,0,0,0,0,1,0", {"cylinder radius", "expected a finite radius > 0, found 0"});
    refused("cylinder:0,0,0,0,0,1,-3", {"cylinder radius", "found -3"});
    refused("cylinder:1,1,0,1,1,0,1", {"zero length"});
    refused("well:P1,0", {"well radius"});
    refused("mesh:", {"mesh: expected a file name"});
    // Every front end shares the options: animate and the viewer refuse before a window opens.
    expect_refused(cutaway({"view", grid.string(), "--cut-volume", "box:1"}), {"--cut-volume", "expected 6 numbers"});
    expect_refused(cutaway({"animate", grid.string(), "--property", "PORO", "--cut-volume", "box:1", "--out", out("a.mp4")}),
                   {"--cut-volume", "expected 6 numbers"});
    expect_no_output();
}

TEST_F(BadInput, PrimariesNoneNeedsAVolumeAndNoSelection) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    expect_refused(cutaway({"render", grid.string(), "--primaries", "none", "--out", out("x.png")}),
                   {"--primaries none", "expected --cut-volume or --cut-volumes"});
    expect_refused(cutaway({"render", grid.string(), "--primaries", "none", "--cut-volume", "box:0,0,0,1,1,1", "--range", "0",
                            "1", "--out", out("x.png")}),
                   {"--primaries none", "--range selects primaries"});
    expect_refused(cutaway({"render", grid.string(), "--primaries", "none", "--cut-volume", "box:0,0,0,1,1,1", "--only",
                            "primaries", "--out", out("x.png")}),
                   {"--primaries none", "--only primaries would draw nothing"});
    expect_refused(cutaway({"render", grid.string(), "--primaries", "some", "--out", out("x.png")}),
                   {"--primaries", "expected one of property|none"});
    expect_no_output();
}

TEST_F(BadInputGl, UnknownWellsAndBadMeshFilesAreRefused) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const auto refused = [&](const std::string& spec, const std::vector<std::string>& fragments,
                             const std::vector<std::string>& more = {}) {
        std::vector<std::string> args = {"--no-metrics", "--cut-volume", spec, "--out", out("x.png"), "--stats", out("x.json")};
        args.insert(args.end(), more.begin(), more.end());
        std::vector<std::string> expected = fragments;
        expected.push_back("--cut-volume '" + spec + "'");
        expect_refused(render(grid, args), expected);
    };
    refused("well:P1", {"unknown well P1 (the model has no wells)"});
    refused("mesh:" + file("open.obj", cube_obj(5)).string(), {"expected a closed mesh, found boundary edges"});
    std::string two = cube_obj() + "v 2 2 0\nv 2 1 0\nv 2 2 1\nv 2 1 1\nv 1 2 0\nv 1 2 1\n"
                                   "f 3 13 9 10\nf 7 12 11 14\nf 3 10 12 7\nf 10 9 11 12\nf 9 13 14 11\nf 13 3 7 14\n";
    refused("mesh:" + file("two.obj", two).string(), {"non-manifold"});
    refused("mesh:" + (fs::path("missing") / "salt.ply").string(), {"expected a readable mesh file, found"});
    // 100 KB of mesh needs about 3 MiB to read, beyond what a 2 MiB limit leaves after the frame.
    const fs::path big = file("big.obj", cube_obj() + std::string(100000, '#') + "\n");
    refused("mesh:" + big.string(), {"--memory-limit-gb"}, {"--memory-limit-gb", "0.002"});
    expect_no_output();
}

TEST_F(BadInputGl, BadCutVolumeListsAreRefusedNamingTheField) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const auto refused = [&](const std::string& text, const std::vector<std::string>& fragments) {
        const fs::path list = file("v.json", text);
        std::vector<std::string> expected = fragments;
        expected.push_back(list.string());
        expect_refused(render(grid, {"--no-metrics", "--cut-volumes", list.string(), "--out", out("x.png")}), expected);
    };
    refused("{\"volumes\": [", {"syntax error"});
    refused(R"({"volumes": [{"kind": "box", "min": [0, 0, 0], "max": [1, 1, 0]}]})", {"volumes[0]: box: zero extent along z"});
    refused(R"({"volumes": [{"kind": "cylinder", "from": [0, 0, 0], "to": [0, 0, 1]}]})", {"volumes[0].radius: missing"});
    // A mesh the list names is looked for beside the list, and named with that folder.
    const fs::path list = file("m.json", R"({"volumes": [{"kind": "mesh", "file": "none.obj"}]})");
    expect_refused(render(grid, {"--no-metrics", "--cut-volumes", list.string(), "--out", out("x.png")}),
                   {(list.parent_path() / "none.obj").string(), "expected a readable mesh file"});
    expect_refused(render(grid, {"--no-metrics", "--cut-volumes", "none.json", "--out", out("x.png")}),
                   {"--cut-volumes none.json", "expected a readable JSON file"});
    expect_no_output();
}

}  // namespace
