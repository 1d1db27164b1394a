#include "cutaway/active_cell_rank.h"

namespace cutaway::pipeline {

ActiveCellRank::ActiveCellRank(const std::vector<std::uint8_t>& actnum)
    : actnum_(actnum), active_before_block_((actnum.size() + block - 1) / block) {
    std::uint32_t active = 0;
    for (std::size_t cell = 0; cell < actnum.size(); ++cell) {
        if (cell % block == 0) active_before_block_[cell / block] = active;
        active += actnum[cell] != 0 ? 1u : 0u;
    }
}

std::uint32_t ActiveCellRank::operator()(std::size_t cell) const {
    std::uint32_t rank = active_before_block_[cell / block];
    for (std::size_t before = cell - cell % block; before < cell; ++before) rank += actnum_[before] != 0 ? 1u : 0u;
    return rank;
}

}  // namespace cutaway::pipeline
