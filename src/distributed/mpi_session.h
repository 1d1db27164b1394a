#pragma once
// The MPI process group of one `mpirun -np N cutaway render` run (MPI_COMM_WORLD), with the few
// collectives the distributed frame needs. This header does not include mpi.h: only
// src/distributed/*.cpp do (DESIGN.md: nothing else includes MPI).
#include <cstdint>
#include <string>
#include <vector>

namespace cutaway::distributed {

class MpiSession {
public:
    /// MPI_Init; throws std::runtime_error if MPI cannot start.
    MpiSession();
    ~MpiSession();  ///< MPI_Finalize
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool root() const { return rank_ == 0; }

    /// Collective: the message of the lowest-numbered rank whose `own_error` is not empty ("" when
    /// every rank succeeded), so all ranks leave a phase together and rank 0 can report why.
    std::string first_error(const std::string& own_error) const;
    /// Ends every rank of the run with `code` (for a failure one rank meets alone mid-frame).
    [[noreturn]] void abort(int code) const;

    double max(double value) const;
    std::uint64_t sum(std::uint64_t value) const;
    /// Element-wise over ranks, in place (the same length on every rank); a minimum is the max
    /// of the negated values.
    void max(std::vector<double>& values) const;
    void sum(std::vector<std::uint64_t>& values) const;
    /// `values` (the same length on every rank) of every rank, rank-major, on every rank.
    std::vector<double> all_gather(const std::vector<double>& values) const;
    /// Gathers `values` (the same length on every rank) at rank 0, rank-major; empty elsewhere.
    std::vector<double> gather(const std::vector<double>& values) const;
    void barrier() const;

private:
    int rank_ = 0;
    int size_ = 1;
};

}  // namespace cutaway::distributed
