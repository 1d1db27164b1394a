#pragma once
// An active cell's compact index (its rank among the active cells in Eclipse order) without a
// table of 4 bytes per cell: the active cells before each block of 64 cells are counted once,
// the rest is counted from ACTNUM at each query (0.06 bytes per cell).
#include <cstdint>
#include <vector>

namespace cutaway::pipeline {

class ActiveCellRank {
public:
    /// Keeps a reference to `actnum` (one flag per Eclipse cell), which must outlive it.
    explicit ActiveCellRank(const std::vector<std::uint8_t>& actnum);
    /// Compact index of Eclipse cell `cell`, which must be active.
    std::uint32_t operator()(std::size_t cell) const;

private:
    static constexpr std::size_t block = 64;
    const std::vector<std::uint8_t>& actnum_;
    std::vector<std::uint32_t> active_before_block_;
};

}  // namespace cutaway::pipeline
