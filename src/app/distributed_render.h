#pragma once
// `mpirun -np N cutaway render ...`: one frame across N ranks (SPEC.md section 7). Each rank draws
// one slab of the model; the cut depth is combined by MPI_Allreduce(MAX) after stage 1, the
// G-buffer composited by IceT after stage 3, and rank 0 runs the screen-space passes and writes
// --out, --cell-ids and --stats. Built with CUTAWAY_MPI; without it the call says so (exit 2).
#include "app_core/render_options.h"

namespace cutaway::app {

int run_distributed_render(const RenderOptions& options);

}  // namespace cutaway::app
