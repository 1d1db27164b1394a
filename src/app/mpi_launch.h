#pragma once
// Whether this process was started by an MPI launcher (mpirun, mpiexec, srun with PMI/PMIx): then
// `cutaway render` renders across the launched ranks (distributed_render.h). Read from the
// environment the launchers set, so a plain run never starts MPI.
#include <cstdlib>

namespace cutaway::app {

inline bool launched_by_mpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK", "MV2_COMM_WORLD_SIZE"})
        if (std::getenv(name)) return true;
    return false;
}

/// This process's rank as the launcher set it (before MPI starts), 0 without a launcher.
inline int mpi_rank_from_launcher() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK", "MV2_COMM_WORLD_RANK"})
        if (const char* value = std::getenv(name)) return std::atoi(value);
    return 0;
}

}  // namespace cutaway::app
