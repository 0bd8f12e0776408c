#pragma once
// The advancing front on several threads. The container's bounding box is cut into
// blocks (front/block_layout.hpp); each block grows with its own front, neighbour grid and random
// stream. A block picks s0 only inside its box, but towards its neighbours that grow later it
// places particles wherever they touch s0, up to 2 r_max beyond its faces; those stay unpicked:
// its front frozen there, which the neighbour resumes (its fixed particles in its box are its
// initial front). A block grows once every neighbour of lower rank has grown, and never beside
// a growing neighbour: blocks growing at once are at least a block edge (>= 8 r_max) apart,
// beyond what their particles can reach (2 r_max beyond a box, and 2 r_max to touch). A block
// grows against what its earlier neighbours placed within 2 r_max of where it places (fixed:
// obstacles, contact bodies, and in its box its initial front). Its growth is ordered along the
// diagonal (1, 1, 1): a plane sweeping from its low corner, where its earlier neighbours are,
// meeting its high faces and the container's walls obliquely. (Measured in experiments/threads:
// blocks whose centres stopped at their faces left a dense layer of centres under each face and
// a gap over it, the loosest slab of r_max near a face 0.055 below the blocks' inside; resuming
// the frozen front leaves 0.018-0.024, 1.5 r_max beyond the face. Placing beyond the faces
// towards earlier neighbours too changed nothing and doubled the fixed particles. A cap from a
// point beyond the low corner leaves looser seams the nearer the point; a sweep along one axis
// leaves holes where it ends against a wall parallel to its plane.)
//
// The layout depends on the scene only, and a block's input is what its earlier neighbours
// placed: the output is identical for every thread count (1 included). It differs from the single
// front's. Stops: a count or a volume fraction is honoured by growing every block, then keeping
// the particles closest to the seed point (the single front grows closest-first as well); the
// dropped ones are counted (`trimmed`). A time limit stops every block (then the output depends
// on timing, as the single front's does).
#include <algorithm>
#include <array>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <queue>
#include <thread>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/io/scene.hpp"
#include "core/system/parallel_parts.hpp"
#include "front/advancing_front.hpp"
#include "front/block_exchange.hpp"
#include "front/block_layout.hpp"
#include "front/front_block.hpp"

namespace fp {

template <int D, class Model>
class BlockFront {
 public:
  using Result = typename Model::Result;
  using Block = FrontBlock<D, typename Model::Draft>;

  BlockFront(const Container<D>& container, const typename Model::Input& input, const PackerOptions& options,
             const StopCriteria& stop, std::uint64_t seed)
      : container_(container), input_(input), opt_(options), stop_(stop), seed_(seed),
        r_max_(Model::r_max_of(input)),
        layout_(container.bounds(), r_max_, options.block_edge.value_or(0.0)) {}

  const BlockLayout<D>& layout() const { return layout_; }

  Result run(int threads, const ProgressFn& progress = {}) {
    const auto t0 = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    const int n = layout_.count();
    results_.assign(static_cast<std::size_t>(n), Result{});

    Order order(layout_, [](int) { return true; });
    std::mutex m;
    std::condition_variable changed;
    int done = 0;
    std::uint64_t placed = 0;
    double solid = 0, next_progress = 0.5;
    const double measure = container_.measure();
    bool timed_out = false;
    std::exception_ptr error;
    auto work = [&] {
      std::unique_lock<std::mutex> lock(m);
      for (;;) {
        changed.wait(lock, [&] { return order.has_ready() || done == n || error; });
        if (done == n || error) return;
        const int b = order.next();
        lock.unlock();
        Result r;
        std::exception_ptr failed;
        try {
          r = grow_in_time(b, elapsed());
        } catch (...) {
          failed = std::current_exception();
        }
        lock.lock();
        if (failed) {
          if (!error) error = failed;
          changed.notify_all();
          return;
        }
        placed += Model::size(r);
        solid += r.solid_measure;
        timed_out |= r.stop == StopReason::TimeLimit;
        results_[static_cast<std::size_t>(b)] = std::move(r);
        if (progress && elapsed() >= next_progress) {
          progress(placed, elapsed(), solid / measure);
          next_progress = elapsed() + 0.5;
        }
        ++done;
        order.finished(b);
        changed.notify_all();
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min(threads, n); ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);

    Result out = merge(timed_out);
    out.seconds = elapsed();
    return out;
  }

  /// The same packing grown by several processes (MPI ranks), one thread each: process p grows
  /// its blocks (owner()), each once its earlier neighbours are there (the lowest
  /// rank first), receiving the particles of those another process grew and sending its own to
  /// the processes that grow its later neighbours; then process 0 gathers every block and
  /// returns the packing (the others return an empty one). Spheres only (the data of
  /// SphereModel::append_data).
  Result run_distributed(BlockExchange& exchange) {
    const auto t0 = std::chrono::steady_clock::now();
    const int n = layout_.count(), me = exchange.process();
    results_.assign(static_cast<std::size_t>(n), Result{});
    std::vector<int> mine;
    for (int b = 0; b < n; ++b)
      if (owner(b, exchange) == me) mine.push_back(b);
    Order order(layout_, [&](int b) { return owner(b, exchange) == me; });
    auto store = [&](std::pair<int, std::vector<double>>&& m) {  // a block another process grew
      Model::add_data(results_[static_cast<std::size_t>(m.first)], m.second.data(), m.second.size());
      order.finished(m.first);
    };
    bool timed_out = false;
    RankWork work;
    auto since = [](std::chrono::steady_clock::time_point t) {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    for (std::size_t left = mine.size(); left > 0;) {
      while (auto m = exchange.receive(false)) store(std::move(*m));
      if (!order.has_ready()) {
        const auto t = std::chrono::steady_clock::now();
        store(std::move(*exchange.receive(true)));
        work.wait_seconds += since(t);
        continue;
      }
      const int b = order.next();
      const auto t = std::chrono::steady_clock::now();
      std::size_t fixed = 0;
      Result& r = results_[static_cast<std::size_t>(b)] = grow_in_time(b, since(t0), &fixed);
      work.grow_seconds += since(t);
      ++work.blocks;
      work.particles += Model::size(r);
      work.fixed += fixed;
      order.finished(b);
      --left;
      timed_out |= r.stop == StopReason::TimeLimit;
      // Each process growing a later neighbour gets the particles of b those blocks fix (grow()
      // selects the same ones, in the same order, from what it receives).
      std::map<int, std::vector<Block>> readers;  // process -> the later neighbours it grows
      for (const int nb : layout_.neighbours(b))
        if (layout_.rank(nb) > layout_.rank(b) && owner(nb, exchange) != me)
          readers[owner(nb, exchange)].push_back(placements_of(nb));
      for (const auto& [to, theirs] : readers) {
        Result part = r;
        Model::keep_only(part, [&](std::size_t i) {
          const Vec<D>& x = Model::position_of(r, i);
          return std::any_of(theirs.begin(), theirs.end(), [&](const Block& k) { return k.fixes(x); });
        });
        std::vector<double> data;
        Model::append_data(part, data);
        work.doubles_sent += data.size();
        exchange.send(to, b, data);
      }
    }
    // Process 0 gathers the blocks with their counters, [timed out, grid bytes, counters...,
    // particles...], and each process's work as a block of its own (index n + process).
    constexpr std::size_t kHead = 2 + std::size(FrontCounters::kFields);
    std::vector<std::pair<int, std::vector<double>>> own;
    own.emplace_back(n + me, std::vector<double>{static_cast<double>(work.blocks), static_cast<double>(work.particles),
                                                 static_cast<double>(work.fixed), static_cast<double>(work.doubles_sent),
                                                 work.grow_seconds, work.wait_seconds});
    for (const int b : mine) {
      const Result& r = results_[static_cast<std::size_t>(b)];
      std::vector<double> data{r.stop == StopReason::TimeLimit ? 1.0 : 0.0, static_cast<double>(r.grid_bytes)};
      for (const auto& f : FrontCounters::kFields) data.push_back(static_cast<double>(r.counters.*f.member));
      Model::append_data(r, data);
      own.emplace_back(b, std::move(data));
    }
    std::vector<std::vector<double>> all = exchange.gather(own, n + exchange.processes());
    if (me != 0) return Result{};
    for (int b = 0; b < n; ++b) {
      const std::vector<double>& data = all[static_cast<std::size_t>(b)];
      Result r;
      if (data.size() >= kHead) {
        timed_out |= data[0] != 0.0;
        r.grid_bytes = static_cast<std::size_t>(data[1]);
        std::size_t k = 2;
        for (const auto& f : FrontCounters::kFields) r.counters.*f.member = static_cast<std::uint64_t>(data[k++]);
        Model::add_data(r, data.data() + kHead, data.size() - kHead);
      }
      results_[static_cast<std::size_t>(b)] = std::move(r);
    }
    Result out = merge(timed_out);
    for (int p = 0; p < exchange.processes(); ++p) {
      const std::vector<double>& w = all[static_cast<std::size_t>(n + p)];
      if (w.size() == 6)
        out.ranks.push_back({static_cast<std::uint64_t>(w[0]), static_cast<std::uint64_t>(w[1]), static_cast<std::uint64_t>(w[2]),
                             static_cast<std::uint64_t>(w[3]), w[4], w[5]});
    }
    out.seconds = since(t0);
    return out;
  }

 private:
  /// The order of growth as blocks finish: how many earlier (lower-rank) neighbours each block
  /// still waits for, and the blocks ready to grow, lowest rank first, among those `takes`
  /// accepts (this process's).
  class Order {
   public:
    template <class Takes>
    Order(const BlockLayout<D>& layout, Takes&& takes) : layout_(layout), waiting_(static_cast<std::size_t>(layout.count()), 0) {
      later_.resize(waiting_.size());
      takes_.resize(waiting_.size());
      for (int b = 0; b < layout.count(); ++b) {
        takes_[static_cast<std::size_t>(b)] = takes(b);
        for (const int nb : layout.neighbours(b))
          if (layout.rank(nb) < layout.rank(b)) ++waiting_[static_cast<std::size_t>(b)];
          else later_[static_cast<std::size_t>(b)].push_back(nb);
        make_ready_if_free(b);
      }
    }
    bool has_ready() const { return !ready_.empty(); }
    int next() {
      const int b = ready_.top().second;
      ready_.pop();
      return b;
    }
    /// Block b is there (grown here or received): its later neighbours wait for one block less.
    void finished(int b) {
      for (const int nb : later_[static_cast<std::size_t>(b)]) {
        --waiting_[static_cast<std::size_t>(nb)];
        make_ready_if_free(nb);
      }
    }

   private:
    void make_ready_if_free(int b) {
      if (waiting_[static_cast<std::size_t>(b)] == 0 && takes_[static_cast<std::size_t>(b)]) ready_.push({layout_.rank(b), b});
    }
    const BlockLayout<D>& layout_;
    std::vector<int> waiting_;
    std::vector<std::vector<int>> later_;
    std::vector<char> takes_;
    std::priority_queue<std::pair<int, int>, std::vector<std::pair<int, int>>, std::greater<>> ready_;  // (rank, block)
  };

  /// grow() with what is left of the scene's time limit after `elapsed` seconds; counts and
  /// fractions are honoured after growth (the class comment). None left: an empty block.
  Result grow_in_time(int b, double elapsed, std::size_t* fixed = nullptr) const {
    StopCriteria s;
    if (stop_.time_limit_seconds) {
      s.time_limit_seconds = *stop_.time_limit_seconds - elapsed;
      if (!(*s.time_limit_seconds > 0)) {
        Result r;
        r.stop = StopReason::TimeLimit;
        return r;
      }
    }
    return grow(b, s, fixed);
  }

  /// Where block b places particles (its box, and 2 r_max beyond the sides whose neighbour
  /// grows later: what touches an s0 of its box, its frozen front there), and how near that its
  /// earlier neighbours' particles are fixed: two particles touch only within 2 r_max of each
  /// other (the margin covers the contact tolerance and the rounding of the distance).
  Block placements_of(int b) const {
    Block block;
    block.box = layout_.box(b);
    block.reach = 2 * r_max_;
    block.halo = 2 * r_max_ * (1 + 1e-6);
    const int rank = layout_.rank(b);
    const std::array<int, D> at = layout_.coords(b);
    block.open_side[Block::kInside] = true;
    for (const int nb : layout_.neighbours(b)) {
      if (layout_.rank(nb) < rank) continue;
      const std::array<int, D> k = layout_.coords(nb);
      int side = 0;
      for (int a = D - 1; a >= 0; --a) side = 3 * side + (k[a] - at[a] + 1);
      block.open_side[static_cast<std::size_t>(side)] = true;
    }
    return block;
  }

  /// Grows block b against the particles its earlier neighbours placed near where it places
  /// (their number in *fixed, if given).
  Result grow(int b, const StopCriteria& stop, std::size_t* fixed = nullptr) const {
    Block block = placements_of(b);
    const int rank = layout_.rank(b);
    for (const int nb : layout_.neighbours(b)) {
      if (layout_.rank(nb) > rank) continue;  // grows later: nothing placed yet
      const Result& r = results_[static_cast<std::size_t>(nb)];
      for (std::size_t i = 0; i < Model::size(r); ++i) {
        const Vec<D>& x = Model::position_of(r, i);
        if (!block.fixes(x)) continue;
        block.fixed_drafts.push_back(Model::draft_of(r, i));
        block.fixed_positions.push_back(x);
      }
    }
    if (fixed) *fixed = block.fixed_positions.size();
    AdvancingFront<D, Model> front(container_, input_, opt_, stop, block_seed(b), &block);
    return front.run();
  }

  /// The process that grows block b: blocks dealt out in turn in index order (along x, then y,
  /// then z), so every process has blocks ready all along the order of growth (ranges along x
  /// made each process's part of a row wait for the part before it: million on 2 ranks packed in
  /// 23.2 s, dealt out in 19.7 s, as 2 threads; experiments/scale simulates up to 1,000 ranks).
  int owner(int b, const BlockExchange& exchange) const { return b % exchange.processes(); }

  /// A block's random stream: the scene's seed and the block's index, spread by splitmix64 (Rng).
  std::uint64_t block_seed(int b) const { return seed_ + 0x9E3779B97F4A7C15ULL * (static_cast<std::uint64_t>(b) + 1); }

  /// The blocks' particles in block order, trimmed to the stop's count or fraction; the blocks'
  /// results are released as they are copied.
  Result merge(bool timed_out) {
    std::size_t total = 0;
    for (const Result& r : results_) total += Model::size(r);
    const std::vector<char> keep = kept_by_stop(total);
    std::size_t kept = 0;

    Result out;
    Model model(container_, input_, opt_, layout_.box(0));  // sets the tolerance, origin, names
    model.attach(out, stop_);
    std::size_t flat = 0;
    for (Result& r : results_) {
      for (std::size_t i = 0; i < Model::size(r); ++i, ++flat)
        if (keep.empty() || keep[flat]) Model::append(out, r, i), ++kept;
      out.counters += r.counters;
      out.never_fit_radii.insert(out.never_fit_radii.end(), r.never_fit_radii.begin(), r.never_fit_radii.end());
      out.solver += r.solver;
      out.grid_bytes = std::max(out.grid_bytes, r.grid_bytes);
      out.grid_levels = std::max(out.grid_levels, r.grid_levels);
      r = Result{};
    }
    out.counters.blocks = static_cast<std::uint64_t>(layout_.count());
    out.counters.trimmed = total - kept;
    if (timed_out) out.stop = StopReason::TimeLimit;
    else if (stop_.max_particles && kept == *stop_.max_particles) out.stop = StopReason::ParticleCount;
    else if (stop_.target_volume_fraction && kept < total) out.stop = StopReason::VolumeFraction;
    else out.stop = StopReason::FrontExhausted;
    return out;
  }

  /// Per particle (in block order): kept by the count or fraction stop, the ones closest to the
  /// seed point first (ties by order). Empty: no such stop, keep all.
  std::vector<char> kept_by_stop(std::size_t total) const {
    if (!stop_.max_particles && !stop_.target_volume_fraction) return {};
    struct Ref {
      double d2;
      std::size_t flat;
      std::uint32_t block, i;
    };
    const Vec<D> seed_point = front_parts::local_seed_point<D>(container_, opt_);
    std::vector<Ref> refs;
    refs.reserve(total);
    for (std::size_t b = 0; b < results_.size(); ++b)
      for (std::size_t i = 0; i < Model::size(results_[b]); ++i)
        refs.push_back({(Model::position_of(results_[b], i) - seed_point).squaredNorm(), refs.size(),
                        static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(i)});
    std::sort(refs.begin(), refs.end(), [](const Ref& a, const Ref& c) { return a.d2 < c.d2 || (a.d2 == c.d2 && a.flat < c.flat); });
    std::size_t kept = stop_.max_particles ? std::min<std::size_t>(total, *stop_.max_particles) : total;
    if (stop_.target_volume_fraction) {
      const double target = *stop_.target_volume_fraction * container_.measure();
      double solid = 0;
      std::size_t k = 0;
      for (; k < kept && solid < target; ++k) solid += Model::measure_of(results_[refs[k].block], refs[k].i);
      kept = k;
    }
    std::vector<char> keep(total, 0);
    for (std::size_t k = 0; k < kept; ++k) keep[refs[k].flat] = 1;
    return keep;
  }

  const Container<D>& container_;
  const typename Model::Input& input_;
  PackerOptions opt_;
  StopCriteria stop_;
  std::uint64_t seed_;
  double r_max_;
  BlockLayout<D> layout_;
  std::vector<Result> results_;  // per block
};

}  // namespace fp
