#pragma once
// MPI for `frontpack pack` (built with FRONTPACK_MPI=ON): under `mpirun -np K`, the K ranks grow
// the blocks of one packing together (front/block_front.hpp) through this exchange; rank 0
// gathers it, checks it, writes it and prints the summary. Without mpirun the command runs alone
// and never initialises MPI.
#include <memory>

#include "front/block_exchange.hpp"

namespace fp {

/// MPI_Init on construction, MPI_Finalize on destruction (after every pending send completed).
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  BlockExchange& exchange();
  /// Ends every rank with this exit code (a rank that failed would leave the others waiting).
  [[noreturn]] void abort(int code);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fp
