#include "cli/mpi_exchange.hpp"

#include <mpi.h>

#include <cstdlib>
#include <deque>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fp {

namespace {

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed (code " + std::to_string(code) + ")");
}

class MpiExchange final : public BlockExchange {
 public:
  MpiExchange() {
    check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
    check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
    int flag = 0;
    void* ub = nullptr;
    check(MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_TAG_UB, &ub, &flag), "MPI_Comm_get_attr");
    tag_ub_ = flag ? *static_cast<int*>(ub) : 32767;
  }
  ~MpiExchange() override { wait_all(); }

  int processes() const override { return size_; }
  int process() const override { return rank_; }

  void send(int to, int block, std::vector<double> data) override {
    Pending& p = pending_.emplace_back();
    p.data = std::move(data);
    check(MPI_Isend(p.data.data(), static_cast<int>(p.data.size()), MPI_DOUBLE, to, tag(block), MPI_COMM_WORLD, &p.request),
          "MPI_Isend");
  }

  std::optional<std::pair<int, std::vector<double>>> receive(bool wait) override {
    MPI_Status status;
    int arrived = 1;
    if (wait) check(MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status), "MPI_Probe");
    else check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status), "MPI_Iprobe");
    if (!arrived) return std::nullopt;
    int count = 0;
    check(MPI_Get_count(&status, MPI_DOUBLE, &count), "MPI_Get_count");
    std::vector<double> data(static_cast<std::size_t>(count));
    check(MPI_Recv(data.data(), count, MPI_DOUBLE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "MPI_Recv");
    return std::make_pair(status.MPI_TAG, std::move(data));
  }

  std::vector<std::vector<double>> gather(const std::vector<std::pair<int, std::vector<double>>>& mine, int blocks) override {
    // Each rank's blocks as one buffer: [block, length, data...] per block, gathered on rank 0.
    std::vector<double> buffer;
    for (const auto& [b, data] : mine) {
      buffer.push_back(b);
      buffer.push_back(static_cast<double>(data.size()));
      buffer.insert(buffer.end(), data.begin(), data.end());
    }
    const int length = static_cast<int>(buffer.size());
    std::vector<int> lengths(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    check(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
    std::vector<double> all;
    if (rank_ == 0) {
      long long total = 0;
      for (int r = 0; r < size_; ++r) offsets[static_cast<std::size_t>(r)] = static_cast<int>(total), total += lengths[static_cast<std::size_t>(r)];
      if (total > 2147483647LL) throw std::runtime_error("MPI: the gathered packing exceeds 2^31 doubles; write per-rank files instead");
      all.resize(static_cast<std::size_t>(total));
    }
    check(MPI_Gatherv(buffer.data(), length, MPI_DOUBLE, all.data(), lengths.data(), offsets.data(), MPI_DOUBLE, 0,
                      MPI_COMM_WORLD),
          "MPI_Gatherv");
    std::vector<std::vector<double>> out;
    if (rank_ != 0) return out;
    out.resize(static_cast<std::size_t>(blocks));
    for (std::size_t k = 0; k + 1 < all.size();) {
      const auto b = static_cast<std::size_t>(all[k]);
      const auto n = static_cast<std::size_t>(all[k + 1]);
      out[b].assign(all.begin() + static_cast<std::ptrdiff_t>(k + 2), all.begin() + static_cast<std::ptrdiff_t>(k + 2 + n));
      k += 2 + n;
    }
    return out;
  }

  void wait_all() {
    for (Pending& p : pending_) MPI_Wait(&p.request, MPI_STATUS_IGNORE);
    pending_.clear();
  }

 private:
  struct Pending {
    std::vector<double> data;
    MPI_Request request{};
  };
  int tag(int block) const {
    if (block > tag_ub_) throw std::runtime_error("MPI: block " + std::to_string(block) + " beyond the largest message tag");
    return block;
  }

  int size_ = 1, rank_ = 0, tag_ub_ = 32767;
  std::deque<Pending> pending_;  // a deque: the buffers of pending sends never move
};

}  // namespace

struct MpiSession::Impl {
  std::unique_ptr<MpiExchange> exchange;
};

MpiSession::MpiSession(int* argc, char*** argv) : impl_(std::make_unique<Impl>()) {
  check(MPI_Init(argc, argv), "MPI_Init");
  impl_->exchange = std::make_unique<MpiExchange>();
}

MpiSession::~MpiSession() {
  impl_->exchange->wait_all();
  impl_->exchange.reset();
  MPI_Finalize();
}

BlockExchange& MpiSession::exchange() { return *impl_->exchange; }

void MpiSession::abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);  // not reached: MPI_Abort ends the process
}

}  // namespace fp
