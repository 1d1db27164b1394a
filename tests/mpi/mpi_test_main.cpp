// main of cutaway_mpi_tests, run as `mpirun -np N cutaway_mpi_tests`: MPI for the whole program,
// one EGL context per rank (gl_test_support.h); only rank 0 prints GoogleTest's report.
#include <gtest/gtest.h>

#include "distributed/mpi_session.h"
#include "gl_test_support.h"
#include "mpi_test_support.h"

namespace cutaway::test {
namespace {
const distributed::MpiSession* session = nullptr;
}  // namespace

const distributed::MpiSession& mpi() { return *session; }

}  // namespace cutaway::test

int main(int argc, char** argv) {
    const cutaway::distributed::MpiSession mpi;
    cutaway::test::session = &mpi;
    ::testing::InitGoogleTest(&argc, argv);
    if (!mpi.root()) {
        ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
        delete listeners.Release(listeners.default_result_printer());
    }
    ::testing::AddGlobalTestEnvironment(new cutaway::test::GlEnvironment);
    return RUN_ALL_TESTS();
}
