#include "grid/fault_cover.h"

#include <array>

namespace cutaway::grid {
namespace {

/// One cell's face on the two pillars it shares with the column across: top and bottom depth on
/// each, in the direction of increasing k (depth, or minus an elevation).
struct PillarSpans {
    std::array<double, 2> top{}, bottom{};
};

}  // namespace

bool face_covered_across(const ZcornStore& zcorn, const std::vector<bool>& active, int i, int j, int k, FaceSide side) {
    const int axis = int(side) / 2;
    if (axis == 2) return false;
    const bool plus = int(side) % 2 == 1;
    const GridDims& d = zcorn.dims();
    const int ni = i + (axis == 0 ? (plus ? 1 : -1) : 0), nj = j + (axis == 1 ? (plus ? 1 : -1) : 0);
    if (!d.contains(ni, nj, k) || !active[d.cell_index(ni, nj, k)]) return false;
    const int bit = 1 << axis, other_bit = axis == 0 ? 2 : 1;  // the face's axis, and the one along it
    // Corner c of this cell on the face is corner c ^ bit of the cell across, on the same pillar.
    const auto spans = [&](int ci, int cj, int ck, bool across) {
        PillarSpans s;
        for (int p = 0; p < 2; ++p) {
            const int corner = (plus != across ? bit : 0) | (p ? other_bit : 0);
            s.top[p] = zcorn.corner_depth(ci, cj, ck, corner);
            s.bottom[p] = zcorn.corner_depth(ci, cj, ck, corner | 4);
        }
        return s;
    };
    const PillarSpans face = spans(i, j, k, false);
    // Depth or elevation: k grows along `sign` on both pillars, or the face is not decided.
    const double sign = face.bottom[0] > face.top[0] ? 1.0 : -1.0;
    const auto proper = [&](const PillarSpans& s) {
        return sign * (s.bottom[0] - s.top[0]) > 0 && sign * (s.bottom[1] - s.top[1]) > 0;
    };
    if (!proper(face)) return false;
    // Whether `later` lies at or after `earlier` in the k direction on both pillars.
    const auto reaches = [&](const std::array<double, 2>& later, const std::array<double, 2>& earlier) {
        return sign * (later[0] - earlier[0]) >= 0 && sign * (later[1] - earlier[1]) >= 0;
    };
    // Up the stack (k decreasing) until its top is at or above the face's, then down likewise.
    for (const int step : {-1, 1}) {
        PillarSpans cell = spans(ni, nj, k, true);
        if (!proper(cell)) return false;
        int at = k;
        while (!(step < 0 ? reaches(face.top, cell.top) : reaches(cell.bottom, face.bottom))) {
            const int next_k = at + step;
            if (!d.contains(ni, nj, next_k) || !active[d.cell_index(ni, nj, next_k)]) return false;
            const PillarSpans next = spans(ni, nj, next_k, true);
            const std::array<double, 2>& joint = step < 0 ? next.bottom : next.top;
            const std::array<double, 2>& own = step < 0 ? cell.top : cell.bottom;
            if (joint != own || !proper(next)) return false;  // a gap or an overlap between the two
            cell = next;
            at = next_k;
        }
    }
    return true;
}

}  // namespace cutaway::grid
