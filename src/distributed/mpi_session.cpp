#include "distributed/mpi_session.h"

#include <mpi.h>

#include <stdexcept>

namespace cutaway::distributed {

MpiSession::MpiSession() {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised && MPI_Init(nullptr, nullptr) != MPI_SUCCESS) throw std::runtime_error("MPI_Init failed");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised) MPI_Finalize();
}

std::string MpiSession::first_error(const std::string& own_error) const {
    int failing = own_error.empty() ? size_ : rank_;
    MPI_Allreduce(MPI_IN_PLACE, &failing, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (failing == size_) return {};
    int length = failing == rank_ ? int(own_error.size()) : 0;
    MPI_Bcast(&length, 1, MPI_INT, failing, MPI_COMM_WORLD);
    std::string message = failing == rank_ ? own_error : std::string(std::size_t(length), ' ');
    MPI_Bcast(message.data(), length, MPI_CHAR, failing, MPI_COMM_WORLD);
    return failing == 0 ? message : "rank " + std::to_string(failing) + ": " + message;
}

void MpiSession::abort(int code) const {
    MPI_Abort(MPI_COMM_WORLD, code);
    throw std::runtime_error("MPI_Abort returned");
}

double MpiSession::max(double value) const {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return value;
}

std::uint64_t MpiSession::sum(std::uint64_t value) const {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    return value;
}

void MpiSession::max(std::vector<double>& values) const {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
}

void MpiSession::sum(std::vector<std::uint64_t>& values) const {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
}

std::vector<double> MpiSession::all_gather(const std::vector<double>& values) const {
    std::vector<double> all(values.size() * std::size_t(size_));
    MPI_Allgather(values.data(), int(values.size()), MPI_DOUBLE, all.data(), int(values.size()), MPI_DOUBLE,
                  MPI_COMM_WORLD);
    return all;
}

std::vector<double> MpiSession::gather(const std::vector<double>& values) const {
    std::vector<double> all(root() ? values.size() * std::size_t(size_) : 0);
    MPI_Gather(values.data(), int(values.size()), MPI_DOUBLE, all.data(), int(values.size()), MPI_DOUBLE, 0,
               MPI_COMM_WORLD);
    return all;
}

void MpiSession::barrier() const { MPI_Barrier(MPI_COMM_WORLD); }

}  // namespace cutaway::distributed
