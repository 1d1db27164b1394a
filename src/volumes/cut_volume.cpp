#include "volumes/cut_volume.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cutaway::volumes {
namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string numbers(std::initializer_list<double> values) {
    std::string text;
    for (double v : values) {
        if (!text.empty()) text += ',';
        text += number(v);
    }
    return text;
}

struct SpecText {
    std::string operator()(const BoxVolume& b) const {
        return "box:" + numbers({b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z});
    }
    std::string operator()(const CylinderVolume& c) const {
        return "cylinder:" + numbers({c.from.x, c.from.y, c.from.z, c.to.x, c.to.y, c.to.z, c.radius});
    }
    std::string operator()(const WellVolume& w) const {
        std::string text = "well:" + w.name;
        if (w.radius) text.append(",").append(number(*w.radius));
        return text;
    }
    std::string operator()(const MeshVolume& m) const { return "mesh:" + m.file; }
};

struct KindName {
    const char* operator()(const BoxVolume&) const { return "box"; }
    const char* operator()(const CylinderVolume&) const { return "cylinder"; }
    const char* operator()(const WellVolume&) const { return "well"; }
    const char* operator()(const MeshVolume&) const { return "mesh"; }
};

bool finite(const grid::Point3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

void check_radius(double radius, const char* field) {
    if (!(std::isfinite(radius) && radius > 0))
        throw std::invalid_argument(std::string(field) + ": expected a finite radius > 0, found " + number(radius));
}

struct Check {
    void operator()(const BoxVolume& b) const {
        if (!finite(b.min) || !finite(b.max)) throw std::invalid_argument("box: expected finite corners");
        const char* axes[3] = {"x", "y", "z"};
        const double extent[3] = {b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z};
        for (int axis = 0; axis < 3; ++axis)
            if (!(extent[axis] > 0))
                throw std::invalid_argument(std::string("box: zero extent along ") + axes[axis] +
                                            " (expected two corners that differ on every axis)");
    }
    void operator()(const CylinderVolume& c) const {
        if (!finite(c.from) || !finite(c.to)) throw std::invalid_argument("cylinder: expected finite end points");
        if (c.from.x == c.to.x && c.from.y == c.to.y && c.from.z == c.to.z)
            throw std::invalid_argument("cylinder: zero length (expected two different end points)");
        check_radius(c.radius, "cylinder radius");
    }
    void operator()(const WellVolume& w) const {
        if (w.name.empty()) throw std::invalid_argument("well: expected a well name");
        if (w.radius) check_radius(*w.radius, "well radius");
    }
    void operator()(const MeshVolume& m) const {
        if (m.file.empty()) throw std::invalid_argument("mesh: expected a file name");
    }
};

}  // namespace

void check_volume(const CutVolume& volume) { std::visit(Check{}, volume); }

const char* kind_name(const CutVolume& volume) { return std::visit(KindName{}, volume); }

std::string spec_text(const CutVolume& volume) { return std::visit(SpecText{}, volume); }

}  // namespace cutaway::volumes
