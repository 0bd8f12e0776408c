#pragma once
// The processes a packing in blocks is shared among (front/block_front.hpp: MPI ranks, through
// cli/mpi_exchange.cpp): block data travels as doubles (spheres: per particle its centre's D
// coordinates and its radius). The front knows nothing of MPI; a build without it never
// constructs an exchange.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace fp {

class BlockExchange {
 public:
  virtual ~BlockExchange() = default;
  virtual int processes() const = 0;
  virtual int process() const = 0;  ///< 0 gathers the packing and writes the outputs
  /// Sends the data of `block` to process `to`; returns at once (the data is kept until delivered).
  virtual void send(int to, int block, std::vector<double> data) = 0;
  /// A block's data another process sent here: the next one that has arrived, if any; with
  /// `wait`, the next one to arrive.
  virtual std::optional<std::pair<int, std::vector<double>>> receive(bool wait) = 0;
  /// On process 0: every process's blocks (`mine`: block and data), indexed by block (`blocks`
  /// of them); elsewhere: empty. Every process calls it.
  virtual std::vector<std::vector<double>> gather(const std::vector<std::pair<int, std::vector<double>>>& mine, int blocks) = 0;
};

}  // namespace fp
