#pragma once
// The MPI run of cutaway_mpi_tests (mpi_test_main.cpp).
#include "distributed/mpi_session.h"

namespace cutaway::test {

const distributed::MpiSession& mpi();

}  // namespace cutaway::test
