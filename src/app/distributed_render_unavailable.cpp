// The build without MPI (CUTAWAY_MPI=OFF): a run under mpirun is refused rather than having every
// rank render and write the same files.
#include <stdexcept>

#include "app/distributed_render.h"
#include "app/mpi_launch.h"

namespace cutaway::app {

int run_distributed_render(const RenderOptions&) {
    if (mpi_rank_from_launcher() > 0) return 2;  // rank 0 says why, once
    throw std::invalid_argument(
        "mpirun: this cutaway was built without MPI (CUTAWAY_MPI=OFF); run it without mpirun, or install "
        "libopenmpi-dev and paraview-dev (scripts/install-deps.sh) and rebuild");
}

}  // namespace cutaway::app
