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

}  // namespace cutaway::app
