#pragma once
// The advancing-front packer, paper 002 Pseudocode 1 (Roselló Valera et al. 2015):
//   F = front, S = placed set; draw r; loop: pick s0 in F; V = {s in S : d(c0, c) <= r0 + r_s + 2r};
//   for pairs (si, sj) of V: candidates = f(s0, si, sj, G, V, r); keep one inside G that overlaps
//   nothing in V; on success add it to S and F and draw a new r; if no pair works remove s0 from F.
// In 2D each new disk touches s0 and ONE neighbour, so "pairs" are single neighbours.
//
// One manager for every shape. It sees drafts (particles drawn, not yet placed), positions,
// circumscribed radii and contact bodies; the particle model `Model` does the geometry:
//  * SphereModel (front/sphere_model.hpp): centres and radii, the analytic solver inlined;
//  * ShapeModel (front/shape_model.hpp): shapes and poses, each pair sent to the contact solver
//    the registry picks for the kinds involved (paper 004: wrappers, minimisation).
// What a model provides: the public members of front/sphere_model.hpp, the smallest model (the
// manager uses every one of them); a model whose drafts turn (kTurns: shapes) also the members of
// front/shape_model.hpp's orientation section (orientation and pocket trials, the roll).
// Differences from the paper, each an option measured in experiments/front-levers/RESULTS.md,
// the same for every shape:
//  * walls are bodies (PackerOptions::walls_as_bodies): near the boundary the walls within
//    reach of s0 join V, so particles sit tangent to the container (the paper's listed drawback);
//    every candidate is required to lie fully inside the container, not just its centre.
//  * which s0 (random as the paper, FIFO, or closest to the seed point: compact growth);
//  * pair order (index, or nearest neighbours first) and which candidate to keep (the first
//    found, or the one closest to the seed point over all pairs);
//  * which neighbours serve as contact bodies: all of V (paper) or only those still in F;
//  * with a pool, whether the smallest draft is tried first as a probe (s0 dropped if it fails);
//  * a pool of drafts drawn ahead: a draft that does not fit at s0 waits while the others are
//    tried; every drawn draft is placed except the pool's last few, so the size distribution
//    is not distorted (no particle is ever shrunk or discarded to make it fit). A draft far
//    larger than the others that found no room at a few picks is set aside as waiting and a
//    fresh one drawn in its place, so that drafts with no room (a rare large class) cannot
//    clog the pool; a waiting draft is dropped onto the front at later picks (drop_onto);
//  * non-spherical particles: the orientation is chosen within the template's law, in the frame
//    of the radius from the seed point (no texture about it) or the container's (trials, more
//    orientations tried in the pocket the scan found, then the roll into the pocket;
//    front/radial_frame.hpp, experiments/shape-density/RESULTS.md). The probe of probe_smallest
//    keeps the smallest draft's orientation as drawn.
#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <queue>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/io/scene.hpp"
#include "core/sampling/rng.hpp"
#include "front/closing_lattice.hpp"
#include "front/container_too_small.hpp"
#include "front/front_block.hpp"
#include "front/front_parts.hpp"
#include "front/radial_frame.hpp"
#include "front/pack_result.hpp"
#include "front/sphere_model.hpp"

namespace fp {

template <int D, class Model = SphereModel<D>>
class AdvancingFront {
 public:
  using Draft = typename Model::Draft;
  using Result = typename Model::Result;
  using Block = FrontBlock<D, Draft>;

  /// The whole container; or, with `block`, one block of it (front/block_front.hpp): s0 in
  /// block->box only, centres where block->may_place(), grown from its fixed particles (or from
  /// a void if it has none), growth ordered along block->growth_direction.
  AdvancingFront(const Container<D>& container, const typename Model::Input& input, const PackerOptions& options,
                 const StopCriteria& stop, std::uint64_t seed, const Block* block = nullptr)
      : container_(container), opt_(options), stop_(stop), rng_(seed), block_(block),
        model_(container, input, options, centres_domain(container, block)) {
    if (opt_.radius_pool < 1) throw std::invalid_argument("radius_pool must be >= 1");
    seed_point_ = block ? block->box.lo : front_parts::local_seed_point<D>(container, opt_);
    measure_ = container_.measure();
    // `auto`: on for narrow size ratios where the model measured it free (spheres: 1.2x faster at
    // the same density); shapes pay density for it (experiments/front-levers/RESULTS.md).
    probe_smallest_ = opt_.probe_smallest.value_or(Model::kProbeSmallestByDefault &&
                                                   model_.r_max() <= kProbeRatioLimit * model_.r_min());
    const LargeShares large = large_shares();
    may_wait_ = !Model::kTurns && kWaitRatio * model_.r_min() <= model_.r_max() && large.volume < kMaxLargeShare;
    if constexpr (!Model::kTurns) {
      const bool rare_large = !block && kWaitRatio * model_.r_min() <= model_.r_max() &&
                              large.count_share < kRareLargeCountShare && large.smallest < std::numeric_limits<double>::infinity();
      if (rare_large && large.volume < kMaxLargeShare) start_large_ahead(large.smallest, seed);
      if (rare_large && large.volume >= kMaxLargeShare && fines_fit_on_skeleton(large)) {
        skeleton_first_ = true;
        large_threshold_ = kWaitRatio * model_.r_min();
      }
    }
  }

  Result run(const ProgressFn& progress = {}) {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    started_ = t0;
    Result res;
    model_.attach(res, stop_);
    auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - t0).count(); };

    for (int k = 0; k < opt_.radius_pool; ++k) push_draw(res);
    if (block_) add_fixed();  // no initial cluster: growth starts from them, or from a void
    else initialise(res);

    std::uint64_t iter = 0;
    double next_progress = 0.5;
    res.stop = StopReason::FrontExhausted;
    while (!front_empty() || resume_at_voids(res)) {
      if (const auto reached = count_or_fraction_reached(res)) { res.stop = *reached; break; }
      // A clock read is nothing beside a pick of a general shape (microseconds to a second: a
      // coarser check overshot a 15 s limit by 10 s), but it is beside a sphere's (~10 us).
      if ((++iter % Model::kClockEvery) == 0 && (stop_.time_limit_seconds || progress)) {
        const double t = elapsed();
        if (stop_.time_limit_seconds && t >= *stop_.time_limit_seconds) { res.stop = StopReason::TimeLimit; break; }
        if (progress && t >= next_progress) {
          progress(model_.count(), t, res.solid_measure / measure_);
          next_progress = t + 0.5;
        }
      }
      place_large_ahead(res);
      const int s0 = front_top();
      ++res.counters.front_picks;
      if (!try_place_around(s0, res)) {
        front_pop();
        ++res.counters.front_removals;
      }
    }
    if constexpr (!Model::kTurns)
      if (skeleton_first_ && res.stop == StopReason::FrontExhausted) place_fines(res);
    res.counters.radii_unplaced = pool_.size() + large_pending_.size() + (fines_.size() - fines_next_) + fines_failed_;
    res.counters.radii_never_fit += large_pending_.size();
    for (const Draft& d : large_pending_) res.never_fit_radii.push_back(radius(d));
    for (std::size_t k = 0; k < pool_.size(); ++k)
      if (waiting(k)) {
        ++res.counters.radii_never_fit;
        res.never_fit_radii.push_back(radius(pool_[k]));
      }
    model_.finish(res);
    if (block_) {
      const std::size_t fixed = block_->fixed_positions.size();
      Model::keep_only(res, [&](std::size_t i) { return i >= fixed; });
    }
    res.seconds = elapsed();
    return res;
  }

 private:
  using FrontEntry = front_parts::FrontEntry;
  using Neighbour = front_parts::Neighbour;

  /// Shapes: the time stop is also checked before every solve (a pick among clusters of 50
  /// members took over a minute: a 20 s stop ended at 98 s); a sphere's pick is short enough for
  /// the main loop's check alone.
  bool time_up() const {
    if constexpr (Model::kClockEvery != 1) return false;
    else
      return stop_.time_limit_seconds &&
             std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() >= *stop_.time_limit_seconds;
  }

  /// The next draft of the law. With a rare large class placed ahead (start_large_ahead) a large
  /// draft is set aside for place_large_ahead, or, if one was placed before its turn, it is the
  /// one that was (counted then): the law's next draft is drawn instead.
  Draft draw(Result& res) {
    for (;;) {
      Draft d = model_.draw(rng_);
      if (skeleton_first_) {  // the fines wait for the skeleton (place_fines)
        ++res.counters.radii_drawn;
        if (radius(d) >= large_threshold_) {
          fines_before_large_.push_back(fines_.size());
          return d;
        }
        fines_.push_back(d);
        continue;
      }
      const bool large = lattice_ && radius(d) >= large_threshold_;
      if (large && large_drawn_ahead_ > 0) {
        --large_drawn_ahead_;
        continue;
      }
      ++res.counters.radii_drawn;
      if (!large) return d;
      large_pending_.push_back(d);
    }
  }
  /// A fresh draft at the end of the pool.
  void push_draw(Result& res) {
    pool_.push_back(draw(res));
    misses_.push_back(0);
  }
  static double radius(const Draft& d) { return Model::radius(d); }
  static double rD(const Draft& d) {
    const double r = radius(d);
    return D == 3 ? r * r * r : r * r;
  }

  // ---- the front F ----
  bool front_empty() const {
    return opt_.front_pick == FrontPick::ClosestToSeed ? heap_.empty() : fifo_head_ >= list_.size();
  }
  int front_top() {
    switch (opt_.front_pick) {
      case FrontPick::ClosestToSeed: return heap_.top().id;
      case FrontPick::Fifo: return list_[fifo_head_];
      case FrontPick::Random: {
        // Paper 002: s0 picked at random. Swap the pick to the head so front_pop() is O(1).
        const std::size_t n = list_.size() - fifo_head_;
        const std::size_t k = fifo_head_ + static_cast<std::size_t>(rng_.below(n));
        std::swap(list_[fifo_head_], list_[k]);
        return list_[fifo_head_];
      }
    }
    return -1;
  }
  void front_pop() {
    if (opt_.front_pick == FrontPick::ClosestToSeed) {
      in_front_[heap_.top().id] = 0;
      heap_.pop();
    } else {
      in_front_[list_[fifo_head_]] = 0;
      ++fifo_head_;
    }
    if (fifo_head_ > 4096 && fifo_head_ * 2 > list_.size()) {  // keep the list compact
      list_.erase(list_.begin(), list_.begin() + static_cast<std::ptrdiff_t>(fifo_head_));
      fifo_head_ = 0;
    }
  }
  void front_push(int id, const Vec<D>& c) {
    if (in_front_.size() <= static_cast<std::size_t>(id)) in_front_.resize(static_cast<std::size_t>(id) + 1, 0);
    in_front_[id] = 1;
    // A block picks only its own s0. Beyond its box, where it may place (towards later
    // neighbours) particles stay open, as contact bodies: its frozen front, which the neighbour
    // resumes. In the earlier neighbours' boxes they are closed: those blocks are done there.
    if (block_ && !block_->box.contains(c)) {
      in_front_[id] = block_->may_place(c) ? 1 : 0;
      return;
    }
    if (opt_.front_pick == FrontPick::ClosestToSeed) heap_.push({growth_key(c), id});
    else list_.push_back(id);
  }

  void add_particle(const Draft& d, const Vec<D>& c) {
    front_push(model_.add(d, c), c);
    if (lattice_) {
      lattice_->add_ball(c, radius(d), radius(d) < large_threshold_);
      placed_rD_ += rD(d);
    }
  }

  // ---- a rare large class, placed ahead of the front ----
  /// Sand with some gravel (a law whose drafts kWaitRatio times its smallest radius or more are
  /// under kRareLargeCountShare of them by count) is filled with its large particles placed
  /// ahead of the front, at the rate at which the container closes to them. The front grows from
  /// the seed point; where it comes within a large diameter of a wall, no large particle fits any
  /// more, and that strip closes faster than the small ones fill it: 78 % of a box 5 gravel
  /// diameters wide lies within a gravel diameter of a wall, and placed in their turn 62 of 104
  /// gravel grains found no room (experiments/extremes, "A rare large class"). So a
  /// ClosingLattice follows where a large centre still fits (c: the share of the large centres'
  /// room the small particles have closed) and where a small one does (f: the share of the
  /// container filled). The filled part should hold w_L S c / f of large volume by now (w_L the
  /// law's share of its volume in large drafts, S the volume placed: S / f is what the container
  /// will hold). While less is placed, a large draft is drawn from the law's large class before
  /// its turn and placed, and the law's next large draft is skipped in return (draw()). Volumes,
  /// not counts: the part filled first holds the large ones placed ahead, and a count of
  /// particles per volume taken there (one large one where a thousand small) told the rest of the
  /// container to expect a third of its particles (62 of 83 gravel grains placed; measured). Each
  /// large particle, in its turn or before, is placed at the open lattice point nearest the seed
  /// point (the front's own order), moved towards the seed point until it touches a particle or a
  /// wall. The count of each class stays the law's (the size test checks it).
  /// Spheres, the whole container (not a block of it), and laws whose large drafts hold under
  /// kMaxLargeShare of the volume: where they hold nearly all of it (radii 100 times apart at
  /// 1000 : 1) the small ones only fill their gaps; there a first cluster of small ones at the
  /// seed point closed a box 3 large diameters wide to large centres at once, and the small ones
  /// then filled it at the 1,700 per second of that size ratio (over 10 minutes; measured).
  void start_large_ahead(double smallest_large, std::uint64_t seed) {
    if constexpr (!Model::kTurns) {
      large_rng_.reseed(seed ^ kLargeStreamSalt);
      large_threshold_ = kWaitRatio * model_.r_min();
      // The law's share of its volume in large drafts, w_L, from its share of them by count
      // (exact) and the mean r^D of each class (samples of a fixed seed: the same for every run).
      const double share = model_.share_at_least(large_threshold_);
      Rng sample_rng(kShareSampleSeed);
      double small_sum = 0, large_sum = 0;
      int small_n = 0, large_n = 0;
      for (int t = 0; t < kMaxClassDraws && (small_n < kShareSamples || large_n < kLargeSamples); ++t) {
        const Draft d = model_.draw(sample_rng);
        if (radius(d) < large_threshold_) {
          if (small_n < kShareSamples) small_sum += rD(d), ++small_n;
        } else if (large_n < kLargeSamples) {
          large_sum += rD(d), ++large_n;
        }
      }
      large_mean_rD_ = large_n ? large_sum / large_n : std::pow(smallest_large, D);
      const double small_mean = small_n ? small_sum / small_n : 0;
      large_volume_share_ = share * large_mean_rD_ / (share * large_mean_rD_ + (1 - share) * small_mean);
      lattice_.emplace(container_, kLatticeSpacing * smallest_large, smallest_large, model_.r_min(), kLatticePoints,
                       [&](const Vec<D>& p) { return growth_key(p); });
    }
  }

  /// Places the large drafts drawn, then those due by the shares closed (start_large_ahead).
  void place_large_ahead(Result& res) {
    if (!lattice_) return;
    while (!large_pending_.empty()) {
      if (!place_ahead(large_pending_.back(), res)) return;
      large_pending_.pop_back();
    }
    const double filled = lattice_->closed_small_share();
    if (!(filled > 0)) return;
    // The large ones' r^D due: w_L of what the container will hold (placed / filled), times the
    // share of their centres' room the small ones have closed.
    const double due = large_volume_share_ * placed_rD_ / filled * lattice_->closed_large_share();
    while (large_rD_ + large_mean_rD_ <= due && !count_or_fraction_reached(res)) {
      Draft d = model_.draw(large_rng_);
      while (radius(d) < large_threshold_) d = model_.draw(large_rng_);
      if (!place_ahead(d, res)) return;
      ++large_drawn_ahead_;
      ++res.counters.radii_drawn;
      ++res.counters.radii_drawn_ahead;
    }
  }

  /// At the open lattice point nearest the seed point, moved towards the seed point until it
  /// touches (bisection on its room, as in drop_onto). False when no point has room.
  bool place_ahead(const Draft& d, Result& res) {
    for (std::optional<Vec<D>> p; (p = lattice_->nearest_open_large());) {
      if (model_.room(d, *p) >= 0) {
        double lo = 0, hi = 1;  // hi: *p (room); lo: the seed point
        for (int it = 0; it < 64; ++it) {
          const double mid = 0.5 * (lo + hi);
          (model_.room(d, seed_point_ + mid * (*p - seed_point_)) >= 0 ? hi : lo) = mid;
        }
        const Vec<D> x = seed_point_ + hi * (*p - seed_point_);
        if (fits(d, x)) {
          add_particle(d, x);
          large_rD_ += rD(d);
          ++res.counters.radii_placed_ahead;
          return true;
        }
      }
      lattice_->close_nearest_open_large();  // a draft larger than the lattice's radius
    }
    return false;
  }

  // ---- a skeleton of the large class, then the fines on it ----
  /// Gravel with sand where the gravel holds nearly all of the volume (large drafts, kWaitRatio
  /// times the smallest radius or more, under kRareLargeCountShare of the drafts by count and
  /// kMaxLargeShare of the volume or more: radii 100 times apart at 1000 : 1 put 99.9 % of it in
  /// the gravel). The sand only fills the gravel's gaps, and grown with it from the seed point it
  /// filled the container with sand first: a first cluster of sand closed a box 3 gravel
  /// diameters wide to gravel centres at once, and the sand then filled it at the 1,700 per
  /// second of that size ratio (over 10 minutes; experiments/extremes, "A rare large class"). So
  /// the front packs the gravel alone, as the skeleton, drawing the law in its order and setting
  /// its sand drafts aside (draw()); then each sand grain is put on a skeleton grain picked at
  /// random, touching it at a point picked at random on its free surface. The fines are the
  /// law's drafts up to its next large draft after the last one the skeleton took, so that the
  /// counts of both classes stay a sample of the law (the size test checks them); the sand is
  /// spread over the skeleton as evenly as the skeleton is over the container. A grain of sand
  /// in a gravel's gap touches that gravel: one contact (in a gap-graded soil the fines carry no
  /// load; they count as rattlers).
  void place_fines(Result& res) {
    if constexpr (!Model::kTurns) {
      const std::size_t skeleton = model_.count();
      if (skeleton == 0) return;
      // The law's order: the fines drawn before its large draft after the skeleton's last.
      const std::size_t due = skeleton < fines_before_large_.size() ? fines_before_large_[skeleton] : fines_.size();
      for (std::uint64_t iter = 0; fines_next_ < due; ++fines_next_) {
        if (const auto reached = count_or_fraction_reached(res)) {
          res.stop = *reached;
          return;
        }
        if ((++iter % kFinesClockEvery) == 0 && stop_.time_limit_seconds &&
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() >= *stop_.time_limit_seconds) {
          res.stop = StopReason::TimeLimit;
          return;
        }
        const Draft& d = fines_[fines_next_];
        bool placed = false;
        for (int t = 0; t < kFineTries && !placed; ++t) {
          const auto g = static_cast<int>(rng_.below(skeleton));
          const Vec<D> x = model_.touching(g, d, front_parts::random_unit<D>(rng_));
          if ((placed = fits(d, x))) add_particle(d, x);
        }
        if (placed) {
          ++res.counters.radii_on_skeleton;
        } else {
          ++fines_failed_;
          ++res.counters.radii_never_fit;
          res.never_fit_radii.push_back(radius(d));
        }
      }
    }
  }

  // ---- a block of a decomposed container ----
  /// Where the model's neighbour grid must hold centres: the container, or the block's box
  /// grown by its reach and the halo of fixed particles around that.
  static Aabb<D> centres_domain(const Container<D>& container, const Block* block) {
    Aabb<D> b = container.bounds();
    if (!block) return b;
    b.lo = b.lo.cwiseMax((block->box.lo.array() - block->reach - block->halo).matrix());
    b.hi = b.hi.cwiseMin((block->box.hi.array() + block->reach + block->halo).matrix());
    return b;
  }
  /// The fixed particles get the first ids, all in F (dropped from the result by run()).
  void add_fixed() {
    for (std::size_t i = 0; i < block_->fixed_drafts.size(); ++i)
      add_particle(block_->fixed_drafts[i], block_->fixed_positions[i]);
  }
  /// The order of growth, smallest key first (the front's picks, the candidate kept, the void
  /// seeded): the squared distance to the seed point; in a block, the distance along its growth
  /// direction (< 0 before its low corner, where the fixed particles are).
  double growth_key(const Vec<D>& x) const {
    if (block_) return block_->growth_direction.dot(x - seed_point_);
    return (x - seed_point_).squaredNorm();
  }
  /// A lower bound of growth_key() over the ball (c, reach).
  double growth_key_bound(const Vec<D>& c, double reach) const {
    if (block_) return growth_key(c) - block_->growth_direction.norm() * reach;
    const double d = std::max(0.0, (c - seed_point_).norm() - reach);
    return d * d;
  }
  /// In the block's box, or within its reach towards a neighbour that grows later: blocks
  /// growing at once never place particles that could touch.
  bool in_block(const Vec<D>& x) const { return !block_ || block_->may_place(x); }
  bool fits(const Draft& d, const Vec<D>& x) const { return in_block(x) && model_.fits(d, x); }
  bool fits_strictly(const Draft& d, const Vec<D>& x) const { return in_block(x) && model_.fits_strictly(d, x); }

  /// The front ran empty. If the container still has a void (room for a pooled draft on a
  /// lattice point of spacing ~kVoidSpacing times its radius, touching nothing), growth resumes
  /// there: the particles around each void go back into F with their failure memo cleared; when
  /// no void has new surroundings to reopen, a new initial cluster is started in the void
  /// closest to the seed point (one at a time: growth from it usually fills the rest). Without
  /// this a wide size distribution (r_max/r_min = 50: a small s0 sunk between big neighbours,
  /// pooled radii too small to bridge a gap) or a container with a narrow neck can stop with the
  /// container nearly empty. Voids are sought for the largest waiting draft, then for the
  /// largest of the others, then for the smallest, each on a lattice of its own size: one of the
  /// law's largest radius, or a void only for the largest draft, missed the gaps a packing of
  /// small ones leaves (sand with a grain of gravel per thousand stopped a third full). Returns
  /// false when there is no void: the normal end, at the cost of a lattice sweep per size.
  bool resume_at_voids(Result& res) {
    std::size_t sought[3] = {largest_in_pool(true), largest_in_pool(false), smallest_active()};
    for (int q = 0; q < 3; ++q) {
      if (sought[q] == pool_.size()) continue;
      bool again = false;
      for (int e = 0; e < q; ++e) again |= sought[e] < pool_.size() && radius(pool_[sought[e]]) == radius(pool_[sought[q]]);
      if (!again && resume_at_voids_of(sought[q], res)) return true;
    }
    return false;
  }

  /// resume_at_voids for pool_[largest].
  bool resume_at_voids_of(std::size_t largest, Result& res) {
    const double spacing = Model::kVoidSpacing * radius(pool_[largest]);
    std::unordered_set<std::int64_t>& reopened_points = voids_reopened_[spacing];
    const Aabb<D> box = block_ ? block_->box : container_.bounds();
    bool reopened = false, found = false;
    Vec<D> best;
    std::size_t best_k = largest;
    double best_key = std::numeric_limits<double>::infinity();
    front_parts::for_each_lattice_point<D>(box, spacing, Model::kVoidPoints,
                                           [&](std::int64_t flat, const Vec<D>& p) {
      const std::optional<std::size_t> k = model_.void_draft(pool_, largest, p);
      if (!k) return;
      if (reopened_points.insert(flat).second) reopened |= reopen_around(p, 3 * radius(pool_[*k]));
      const double key = growth_key(p);
      if (key < best_key) best_key = key, best = p, best_k = *k, found = true;
    }, block_ != nullptr);
    if (reopened) {
      ++res.counters.voids_reopened;
      return true;
    }
    if (!found) return false;
    ++res.counters.voids_seeded;
    return start_cluster(res, best, best_k);
  }

  /// Puts the particles within `reach` of p back into F, their failure memo cleared.
  bool reopen_around(const Vec<D>& p, double reach) {
    bool any = false;
    if (failed_radius_.size() < model_.count()) failed_radius_.resize(model_.count(), std::numeric_limits<double>::infinity());
    model_.grid().for_each_within(p, reach, [&](int id, const Vec<D>& c, double, double) {
      failed_radius_[id] = std::numeric_limits<double>::infinity();
      if (in_front_[id]) return;
      front_push(id, c);
      any = true;
    });
    return any;
  }

  /// The stop criteria that depend only on what has been placed (the time limit is checked in run()).
  std::optional<StopReason> count_or_fraction_reached(const Result& res) const {
    if (stop_.max_particles && model_.count() >= *stop_.max_particles) return StopReason::ParticleCount;
    if (stop_.target_volume_fraction && res.solid_measure >= *stop_.target_volume_fraction * measure_)
      return StopReason::VolumeFraction;
    return std::nullopt;
  }

  /// Step 1 of Pseudocode 1: D mutually tangent particles at the seed point (3 in 3D, 2 in 2D).
  /// Each takes the largest draft of the pool (the pool still follows the requested
  /// distribution): three mutually tangent spheres leave a 4th room only if it is not much
  /// smaller than they are, and a tiny one sunk between two big ones leaves none.
  void initialise(Result& res) {
    // The largest pooled draft the container can hold at all (a thin container may not take r_max).
    const Vec<D> deep = container_.interior_point();
    std::size_t k = pool_.size();
    for (std::size_t q = 0; q < pool_.size(); ++q)
      if (model_.fits(pool_[q], deep) && (k == pool_.size() || radius(pool_[q]) > radius(pool_[k]))) k = q;
    if (k == pool_.size())  // the scene's fault (for shapes the scene check cannot tell): bad input
      throw ContainerTooSmall("the container cannot hold a first particle of (circumscribed) radius " +
                               std::to_string(radius(pool_[0])) +
                               " at its interior point: container too small for the size distribution");
    start_cluster(res, seed_point_, k);
  }

  /// D mutually tangent particles: the first near `where` (first_centre) with pool_[k1], the
  /// others with the largest pooled drafts, tangent in random directions, where they fit. A
  /// container barely larger than one particle may leave the cluster with fewer. False if the
  /// first does not fit anywhere between `where` and the container's interior point.
  bool start_cluster(Result& res, const Vec<D>& where, std::size_t k1) {
    const std::optional<Vec<D>> c1 = first_centre(pool_[k1], where);
    if (!c1) return false;
    add_particle(take_from_pool(k1, res), *c1);
    const int i1 = static_cast<int>(model_.count()) - 1;
    if (count_or_fraction_reached(res)) return true;  // a stop of 1 particle (or a tiny φ0) is honoured
    int i2 = -1;
    for (int attempt = 0; attempt < 64 && i2 < 0; ++attempt) {
      const std::size_t k2 = largest_in_pool();
      const Vec<D> c2 = model_.touching(i1, pool_[k2], front_parts::random_unit<D>(rng_));
      if (!fits(pool_[k2], c2)) continue;
      add_particle(take_from_pool(k2, res), c2);
      i2 = static_cast<int>(model_.count()) - 1;
    }
    if (i2 < 0) {  // a thin container (slab, needle): search the narrow window of directions
      const std::size_t k2 = largest_in_pool();
      const Draft& d2 = pool_[k2];
      const Vec<D> u = front_parts::direction_with_most_room<D>(Vec<D>::Zero(), 1.0, [&](const Vec<D>& v) {
        return model_.room(d2, model_.beside(i1, d2, v));
      });
      const Vec<D> c2 = model_.touching(i1, d2, u);
      if (fits(d2, c2)) {
        add_particle(take_from_pool(k2, res), c2);
        i2 = static_cast<int>(model_.count()) - 1;
      }
    }
    if constexpr (D == 3) {
      if (i2 < 0 || count_or_fraction_reached(res)) return true;
      const std::size_t k3 = largest_in_pool();
      const Draft& d3 = pool_[k3];
      for (int attempt = 0; attempt < 64; ++attempt) {
        const Vec3 c3 = model_.touching_both(i1, i2, d3, 2 * kPi * rng_.uniform01());  // a random point of it
        if (!fits(d3, c3)) continue;
        add_particle(take_from_pool(k3, res), c3);
        return true;
      }
      // A slab leaves a window of a few degrees: the point with the most room.
      auto room_at = [&](double phi) { return model_.room(d3, model_.beside_both(i1, i2, d3, phi)); };
      constexpr int kSteps = 4096;
      double best_room = -std::numeric_limits<double>::infinity(), best_phi = 0;
      for (int s = 0; s < kSteps; ++s) {
        const double phi = 2 * kPi * s / kSteps, g = room_at(phi);
        if (g > best_room) best_room = g, best_phi = phi;
      }
      for (double step = kPi / kSteps; step > 1e-9; step *= 0.5)
        for (const double phi : {best_phi - step, best_phi + step}) {
          const double g = room_at(phi);
          if (g > best_room) best_room = g, best_phi = phi;
        }
      const Vec3 c3 = model_.touching_both(i1, i2, d3, best_phi);
      if (fits(d3, c3)) add_particle(take_from_pool(k3, res), c3);
    }
    return true;
  }

  /// `where` if the draft fits there (strictly: no tolerance); else the point nearest to it, on
  /// the segment to the container's interior point, where it does (a seed point in a corner is
  /// a common choice). None if it fits nowhere there.
  std::optional<Vec<D>> first_centre(const Draft& d, const Vec<D>& where) const {
    if (fits_strictly(d, where)) return where;
    const Vec<D> deep = container_.interior_point();
    if (fits(d, deep)) {
      double lo = 0, hi = 1;  // fits at hi, not at lo
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (fits_strictly(d, where + mid * (deep - where)) ? hi : lo) = mid;
      }
      const Vec<D> x = where + hi * (deep - where);
      if (fits(d, x)) return x;
    }
    // A void found after the front ran empty, within the tolerance of its walls, with the
    // interior point long occupied: where it is.
    if (fits(d, where)) return where;
    return std::nullopt;
  }

  /// The first pooled draft among those `kept` whose radius no other beats by `before` (strictly);
  /// pool_.size() if none is kept.
  template <class Kept, class Before>
  std::size_t first_in_pool(Kept kept, Before before) const {
    std::size_t k = pool_.size();
    for (std::size_t q = 0; q < pool_.size(); ++q)
      if (kept(q) && (k == pool_.size() || before(radius(pool_[q]), radius(pool_[k])))) k = q;
    return k;
  }
  std::size_t largest_in_pool() const {
    return first_in_pool([](std::size_t) { return true; }, std::greater<double>());
  }
  /// The smallest draft of the pool that is not waiting.
  std::size_t smallest_active() const {
    return first_in_pool([&](std::size_t q) { return !waiting(q); }, std::less<double>());
  }
  /// The largest waiting (or not waiting) draft of the pool; pool_.size() if there is none.
  std::size_t largest_in_pool(bool waiting_ones) const {
    return first_in_pool([&](std::size_t q) { return waiting(q) == waiting_ones; }, std::greater<double>());
  }

  /// The law's drafts kWaitRatio times its smallest radius or more: their share of its volume and
  /// of its drafts, and the smallest of them (estimated from a fixed sample: the same for every seed).
  struct LargeShares {
    double volume = 1;       // of the law's volume
    double count_share = 1;  // of its drafts by count
    double smallest = std::numeric_limits<double>::infinity();  // the smallest large draft sampled
    double largest_small = 0;  // the largest small draft sampled
  };
  LargeShares large_shares() {
    Rng sample_rng(kShareSampleSeed);
    double all = 0, large = 0;
    LargeShares shares;
    int large_count = 0;
    for (int s = 0; s < kShareSamples; ++s) {
      const Draft d = model_.draw(sample_rng);
      const double r = radius(d), v = rD(d);
      all += v;
      if (r >= kWaitRatio * model_.r_min()) large += v, ++large_count, shares.smallest = std::min(shares.smallest, r);
      else shares.largest_small = std::max(shares.largest_small, r);
    }
    shares.volume = all > 0 ? large / all : 1.0;
    shares.count_share = double(large_count) / kShareSamples;
    return shares;
  }

  /// Whether a skeleton grain's surface takes its share of the fines (place_fines) with room to
  /// spare: grains of radius r put at random on a grain of radius R cover at most 0.547 of the
  /// sphere of their centres (random sequential adsorption: about 0.547 x 4 (R + r)^2 / r^2 of
  /// them) or 0.7476 of the circle (Renyi: 0.7476 pi (R + r) / r of them), and a grain loses part of
  /// its surface to its neighbours and the walls: half of that. Sand at 1000 : 1 and radii 100
  /// apart fits in 3D (22,000 per grain), not in 2D (240); there the front grows the sand with
  /// the gravel.
  bool fines_fit_on_skeleton(const LargeShares& large) const {
    if (!(large.count_share > 0) || !(large.largest_small > 0)) return false;
    const double per_grain = (1 - large.count_share) / large.count_share;
    const double k = (large.smallest + large.largest_small) / large.largest_small;
    const double fit = D == 3 ? 0.547 * 4 * k * k : 0.7476 * std::numbers::pi * k;
    return per_grain <= 0.5 * fit;
  }

  /// Whether pool_[k] is waiting: set aside after kWaitAfter picks without room, with a fresh
  /// draft drawn beside it (it is not replaced when it is placed).
  bool waiting(std::size_t k) const { return misses_[k] >= kWaitAfter; }

  /// pool_[k] found no room at s0 (kWaitAfter times: it waits). Only a draft kWaitRatio times
  /// the smallest of the others may wait: a narrower law's drafts find room on the front within a
  /// few picks, and are never dropped. The pool holds opt_.radius_pool drafts that are not
  /// waiting, and at most kMaxWaiting that are. Beyond that a draft without room keeps its place,
  /// as every draft did before: the pool clogs, the front runs empty and the void search finds
  /// room ahead for what it holds (hundreds waiting grew the small ones far ahead of the large
  /// ones, and the clog then cost a scan at every s0 of a large front: experiments/extremes,
  /// "A rare large class").
  void missed(std::size_t k, Result& res) {
    if (!may_wait_ || waiting(k) || ++misses_[k] < kWaitAfter) return;
    if (radius(pool_[k]) / radius(pool_[smallest_active()]) < kWaitRatio || waiting_count_ == kMaxWaiting) {
      misses_[k] = kWaitAfter - 1;
      return;
    }
    misses_[k] = kWaitAfter;  // waiting()
    ++waiting_count_;
    ++res.counters.radii_waited;
    push_draw(res);
  }

  Draft take_from_pool(std::size_t k, Result& res) {
    Draft d = std::move(pool_[k]);
    const bool replace = !waiting(k);
    if (!replace) --waiting_count_;
    pool_.erase(pool_.begin() + static_cast<std::ptrdiff_t>(k));
    misses_.erase(misses_.begin() + static_cast<std::ptrdiff_t>(k));
    if (replace) push_draw(res);
    return d;
  }

  /// Step 2.1-2.2 for one s0: returns true if a particle was placed.
  bool try_place_around(int s0, Result& res) {
    if (pool_.size() == 1) {
      gather_neighbours(s0, radius(pool_[0]), res);
      return place(0, s0, res);
    }
    // Pool: try the drafts from the largest down (big particles first keeps small ones for the
    // gaps). A draft at least as large as one that already failed at s0 is not tried there
    // again: s0 stays in F only while a smaller draft fits, so re-trying the large one would
    // repeat a failed scan. (Heuristic: new neighbours can in principle open a new position.)
    // With probe_smallest_ the smallest draft is tried first: if it fails, s0 is dropped after
    // one scan; if it fits, its position is kept in case every larger draft fails.
    // Of the waiting drafts only the largest that may fit is dropped (one drop per pick, however
    // many wait: the next pick of s0 tries the next smaller one).
    if (failed_radius_.size() < model_.count()) failed_radius_.resize(model_.count(), std::numeric_limits<double>::infinity());
    double& failed = failed_radius_[s0];
    order_.clear();
    int waiting_tried = -1;
    for (std::size_t k = 0; k < pool_.size(); ++k) {
      if (!(radius(pool_[k]) < failed)) continue;
      if (!waiting(k)) order_.push_back(static_cast<int>(k));
      else if (waiting_tried < 0 || radius(pool_[k]) > radius(pool_[waiting_tried])) waiting_tried = static_cast<int>(k);
    }
    if (waiting_tried >= 0) {
      const double rw = radius(pool_[waiting_tried]);
      if (drop_onto(static_cast<std::size_t>(waiting_tried), s0, res)) return true;
      failed = std::min(failed, rw);
      // Drafts as large are not tried at s0 either, and miss as it did (else drafts of its size
      // that are not waiting yet never would: the pool clogs again).
      std::size_t kept = 0;
      for (const int k : order_) {
        if (radius(pool_[k]) < failed) order_[kept++] = k;
        else missed(static_cast<std::size_t>(k), res);
      }
      order_.resize(kept);
    }
    if (order_.empty()) return false;
    std::sort(order_.begin(), order_.end(), [&](int a, int b) {
      const double ra = radius(pool_[a]), rb = radius(pool_[b]);
      return ra > rb || (ra == rb && a < b);
    });
    // The largest draft tried sets V (a superset of every smaller draft's V).
    gather_neighbours(s0, radius(pool_[order_[0]]), res);
    std::size_t larger = order_.size();  // order_[0, larger) are tried largest first
    Found at_smallest;
    if (probe_smallest_ && order_.size() >= 2) {
      const Draft& d = pool_[order_.back()];
      if (!find_position(d, s0, res, at_smallest)) {
        failed = std::min(failed, radius(d));
        return false;
      }
      --larger;
    }
    for (std::size_t q = 0; q < larger; ++q) {
      const int k = order_[q];
      // A sphere as large as one that just failed here fails the same scan (a discrete law's
      // drafts of one radius: a pool clogged with large ones scanned each at every s0).
      if (!Model::kTurns && !(radius(pool_[k]) < failed)) {
        missed(static_cast<std::size_t>(k), res);
        continue;
      }
      if (place(static_cast<std::size_t>(k), s0, res)) return true;
      failed = std::min(failed, radius(pool_[k]));
      missed(static_cast<std::size_t>(k), res);
    }
    if (larger == order_.size()) return false;
    add_particle(take_from_pool(static_cast<std::size_t>(order_.back()), res), at_smallest.position);
    return true;
  }

  /// A waiting draft (as a rule far larger than s0's neighbours: a rare large class) has no
  /// position touching s0 and two bodies: s0 is the particle closest to the seed point, a hollow
  /// of the front, and a large particle resting on the crests around it touches neither s0 nor,
  /// mostly, two of the contact bodies the scan offers (with a crest as s0 instead, 56 of 100
  /// gravel grains placed in a box of 5 of their diameters, at a full pair scan per pick). It is
  /// dropped onto the front instead: from up to 2 of its radii beyond s0, on the line from the seed
  /// point through s0 (a block: along its growth direction), towards s0 until it touches what is
  /// there, s0 or another (bisection on its room: the gap it keeps is below the contact
  /// tolerance; a shape's, not only its circumscribed sphere's). One touch,
  /// ahead of the front: the particles grown around it later give it its other contacts. False
  /// where the start is not free (the front is not open above s0). One room query per step.
  bool drop_onto(std::size_t k, int s0, Result& res) {
    const Draft& d = pool_[k];
    const double r = radius(d);
    const Vec<D> c0 = model_.position(s0);
    Vec<D> u = block_ ? block_->growth_direction : Vec<D>(c0 - seed_point_);
    if (!(u.norm() > 0)) return false;
    u.normalize();
    // The start: the nearest of a few points beyond s0 (their circumscribed spheres touching,
    // then farther) with room: the front is rough.
    Vec<D> start;
    bool open = false;
    for (const double beyond : {0.0, 0.25, 0.5, 1.0, 2.0}) {
      start = c0 + (model_.radius(s0) + (1 + beyond) * r) * u;
      if ((open = in_block(start) && model_.room(d, start) >= 0)) break;
    }
    if (!open) return false;
    double lo = 0, hi = 1;  // room at start (hi), none at c0 (lo: inside s0)
    for (int it = 0; it < 64; ++it) {
      const double mid = 0.5 * (lo + hi);
      (model_.room(d, c0 + mid * (start - c0)) >= 0 ? hi : lo) = mid;
    }
    const Vec<D> x = c0 + hi * (start - c0);
    if (!fits(d, x)) return false;
    ++res.counters.radii_dropped;
    add_particle(take_from_pool(k, res), x);
    return true;
  }

  /// V = particles whose circumscribed spheres come within 2R of s0's (paper's definition), plus
  /// walls within reach; then the contact bodies among them.
  void gather_neighbours(int s0, double R, Result& res) {
    const Vec<D> c0 = model_.position(s0);
    const double r0 = model_.radius(s0);
    // Nearest first: the candidate overlap test stops earliest this way.
    front_parts::gather_v<D>(model_.grid(), container_, opt_, s0, c0, r0, R, nb_, walls_, res.counters);
    // Pair enumeration: walls first (few, and they close the boundary gap), then V nearest first.
    bodies_.clear();
    model_.add_wall_bodies(s0, R, walls_, bodies_);
    // A closed particle (no longer in F) rarely has room left next to it: skipping it as a contact
    // body (it stays an obstacle in V) removes most pairs (experiments/front-levers).
    const bool front_only = opt_.contact_bodies == ContactBodies::Front;
    // The 3D pair scan is quadratic in the contact bodies. A mobile far larger than s0 (a wide
    // size distribution: a big radius tried next to small particles) has a V of thousands of
    // small neighbours; its pairs are limited to the kMaxContactBodies nearest (it stays checked
    // against all of V), which bounds the cost of each try. Narrow distributions have |V| < 80
    // (the counter max_neighbours; contact bodies are fewer) and never reach the limit. Measured in
    // experiments/extremes: a 99:1 mix of radii 100 (1000) times apart packs in 8.4 (9.4) s, not
    // in over 60 s; 64 leaves the named scenes bit for bit unchanged (32 does not: ratio7).
    std::size_t particles = 0;
    for (const Neighbour& n : nb_) {
      if (front_only && !in_front_[n.id]) continue;
      if (!model_.may_pair_with_s0(s0, n.id, R)) continue;
      if (D == 3 && particles++ == kMaxContactBodies) {  // a 2D scan is linear: no cap
        ++res.counters.contact_bodies_capped;
        break;
      }
      bodies_.push_back(model_.body(n.id));
    }
    model_.neighbours_ready(nb_);
  }

  /// A position found for a draft: where, the bodies it touches besides s0 (indices into bodies_;
  /// 2D: i == j), their rank (0: a wall among them) and its growth key.
  struct Found {
    Vec<D> position = Vec<D>::Zero();
    int i = -1, j = -1;
    int rank = 2;
    double key = 0;
  };

  /// Tries to place pool_[k] touching s0 and D-1 bodies of V; places it and returns true on success.
  bool place(std::size_t k, int s0, Result& res) {
    Found best;
    if (!find_oriented_position(pool_[k], s0, res, best)) return false;
    add_particle(take_from_pool(k, res), best.position);
    return true;
  }

  /// find_position, for a model whose drafts may turn (Model::kTurns, non-spherical particles):
  /// over opt_.orientation_trials orientations (the position kept by the compactness rule over
  /// all of them), then the pocket trials and the roll. What fits in a gap depends on the
  /// orientation far more than on the position (experiments/shape-density). The draft keeps the
  /// orientation of the position returned (a draft not placed keeps its own).
  bool find_oriented_position(Draft& d, int s0, Result& res, Found& best) {
    if constexpr (!Model::kTurns) {
      return find_position(d, s0, res, best);
    } else {
      // Neither the pocket trials nor the roll in a block (threads): its growth is a plane's
      // sweep, and choosing by it lays elongated particles across one direction (13,548 capsules
      // grown in 2 blocks: their axes' azimuth failed the orientation test, p = 4e-40). A block's
      // drafts keep the orientation drawn in the lab frame until placed: the sweep's direction is
      // the same everywhere, so where a draft goes cannot couple its orientation to it.
      const bool keep_first = opt_.candidate == CandidateChoice::First;
      const bool choose = !keep_first && !block_;
      const Mat<D> drawn = model_.orientation(d);
      const bool radial = !block_ && opt_.orientation_frame == OrientationFrame::Radial && model_.isotropic(d);
      // Radial frame: the draft's drawn orientation is read relative to s0's radius; trials turn
      // it about that radius only (3D; 2D: none keeps the angle to it).
      const Vec<D> r0 = model_.position(s0) - seed_point_;
      const int trials = radial && D == 2 ? 1 : model_.orientation_trials(d);
      bool found = false;
      Mat<D> kept = drawn;
      double kept_turn = 0;
      for (int t = 0; t < trials && !(found && keep_first); ++t) {
        double turn = 0;
        if (radial) {
          if (t > 0) turn = 2 * kPi * rng_.uniform01();
          model_.set_orientation(d, at_radius<D>(r0, turn, drawn));
        } else if (t > 0) {
          model_.redraw_orientation(d, rng_);
        }
        if (t > 0) ++res.counters.orientation_draws;
        Found f;
        if (!find_position(d, s0, res, f)) continue;
        if (found && (f.rank > best.rank || (f.rank == best.rank && f.key >= best.key))) continue;
        best = f;
        kept = model_.orientation(d);
        kept_turn = turn;
        found = true;
      }
      if (!found) {
        model_.set_orientation(d, drawn);
        return false;
      }
      model_.set_orientation(d, kept);
      // Radial frame: until the orientation is set relative to the position's own radius, any
      // solution of the pocket trials replaces the scan's, farther or not.
      bool unframed = radial && !reframe(d, best, drawn, kept_turn, res);
      const bool turn = choose && !(radial && D == 2);  // 2D: no turn keeps the angle to the radius
      if (turn && model_.pocket_trials(d) > 0) pocket_trials(d, best, radial ? &drawn : nullptr, unframed, res);
      if (unframed) ++res.counters.reframe_misses;
      if (turn && opt_.roll_steps > 0 && model_.may_roll(d)) roll(d, best, radial, res);
      return true;
    }
  }

  /// Radial frame: the scan placed the draft relative to s0's radius, but the radius that counts
  /// is its own position's, which the scan's choice of the side of s0 couples to the orientation
  /// (capsules: <P2(a.r)> +0.19 without it). The orientation is set again relative to the
  /// position's radius (the same turn about it) and the same pocket solved again; the solution
  /// nearest the scan's is taken even if farther from the seed point. False if none passes the
  /// checks: the scan's is kept.
  bool reframe(Draft& d, Found& best, const Mat<D>& drawn, double turn, Result& res) {
    const Mat<D> scanned = model_.orientation(d);
    std::array<Placement<D>, Model::kMaxPlacements> out;
    model_.begin_roll();
    model_.set_orientation(d, at_radius<D>(best.position - seed_point_, turn, drawn));
    const int m = solve_again(d, best, out, res);
    int q = -1;
    for (int c = 0; c < m; ++c) {
      const Vec<D>& x = out[c].position;
      if (!keeps_pocket(d, x, best)) continue;
      if (q < 0 || (x - best.position).squaredNorm() < (out[q].position - best.position).squaredNorm()) q = c;
    }
    if (q >= 0) {
      best.position = out[q].position;
      best.key = growth_key(best.position);
    } else {
      model_.set_orientation(d, scanned);
    }
    model_.orient(d);
    return q >= 0;
  }

  /// The pocket trials (non-spherical particles, isotropic law): once the scan has found the
  /// pocket (s0 and the bodies i, j of the position kept), other orientations are tried in that
  /// pocket only: the same contact problem solved again at each, and a solution closer to the
  /// seed point that passes the scan's checks is kept with its orientation. What fits a pocket
  /// depends on the orientation far more than on the position, and a trial costs one solve, not a
  /// whole scan as an orientation trial does. Lab frame (relative == nullptr): orientations drawn
  /// from the law; radial frame: the drawn orientation `relative` turned about the position's
  /// radius by a random angle (the relation to the radius stays the law's). With `unframed`
  /// (radial frame, the reframe found no room), the first solution that passes the checks is
  /// taken wherever it lies, and unframed cleared.
  void pocket_trials(Draft& d, Found& best, const Mat<D>* relative, bool& unframed, Result& res) {
    Mat<D> kept = model_.orientation(d);
    const Vec<D> radius = best.position - seed_point_;
    std::array<Placement<D>, Model::kMaxPlacements> out;
    model_.begin_roll();
    for (int t = model_.pocket_trials(d); t > 0; --t) {
      ++res.counters.pocket_draws;
      if (relative) model_.set_orientation(d, at_radius<D>(radius, 2 * kPi * rng_.uniform01(), *relative));
      else model_.redraw_orientation(d, rng_);
      const int m = solve_again(d, best, out, res);
      bool better = false;
      for (int c = 0; c < m; ++c) {
        const Vec<D>& x = out[c].position;
        if ((unframed || growth_key(x) < best.key) && keeps_pocket(d, x, best)) {
          best.position = x;
          best.key = growth_key(x);
          better = true;
          unframed = false;
        }
      }
      if (better) {
        kept = model_.orientation(d);
        ++res.counters.pocket_kept;
      }
    }
    model_.set_orientation(d, kept);
    model_.orient(d);
  }

  /// The roll (non-spherical particles): the draft just positioned turns by small random
  /// rotations within its law (lab frame, model_.turn: about any axis for an isotropic law, about
  /// its own axis for a law about an axis; radial frame: about its position's radius) while
  /// touching s0 and the same bodies: their contact problem is solved again at each orientation
  /// and the solution nearest to the last kept one followed. A turn that brings it closer to the
  /// seed point and passes the scan's checks is kept: the particle rolls or slides into the
  /// pocket its bodies form, until a fourth body stops it. The overlap allowance is a tenth of
  /// the scan's (a roll pushes against that fourth body: with the scan's it ends inside it by the
  /// whole tolerance). The angle grows after a kept turn and shrinks after a refused one; the
  /// roll ends after roll_steps turns or below kMinRollAngle.
  void roll(Draft& d, Found& best, bool radial, Result& res) {
    auto kept = model_.orientation(d);
    double angle = kRollAngle;
    std::array<Placement<D>, Model::kMaxPlacements> out;
    model_.begin_roll();
    for (int t = 0; t < opt_.roll_steps && angle >= kMinRollAngle; ++t) {
      ++res.counters.roll_turns;
      if (radial) model_.set_orientation(d, about_radius<D>(best.position - seed_point_, angle * rng_.uniform(-1.0, 1.0)) * kept);
      else model_.turn(d, angle, rng_);
      const int m = solve_again(d, best, out, res);
      int q = -1;
      for (int c = 0; c < m; ++c)
        if (q < 0 || (out[c].position - best.position).squaredNorm() < (out[q].position - best.position).squaredNorm()) q = c;
      const bool closer = q >= 0 && growth_key(out[q].position) < best.key;
      if (closer && keeps_pocket(d, out[q].position, best)) {
        best.position = out[q].position;
        best.key = growth_key(best.position);
        kept = model_.orientation(d);
        angle = std::min(kMaxRollAngle, 1.5 * angle);
        ++res.counters.roll_kept;
      } else {
        model_.set_orientation(d, kept);
        angle *= 0.7;
      }
    }
    model_.set_orientation(d, kept);
    model_.orient(d);
  }

  /// The pocket of `best` (s0 and its bodies i, j) solved again for the draft's current
  /// orientation (the reframe, the pocket trials, the roll); the solutions' count.
  int solve_again(const Draft& d, const Found& best, std::span<Placement<D>> out, Result& res) {
    if (time_up()) return 0;
    model_.orient(d);
    ++res.counters.solves;
    return model_.solve(best.i, best.j, out);
  }

  /// Whether x, a solution of best's pocket solved again, may be kept: on the faces of the walls
  /// it touches, inside, overlapping nothing beyond kRollAllowance x the tolerance (a turn pushes
  /// against a fourth body: with the scan's allowance it would end inside it by the whole of it).
  bool keeps_pocket(const Draft& d, const Vec<D>& x, const Found& best) {
    return !off_face(d, x, best.i, best.j, best.rank) && rejection(d, x, best.rank, kRollAllowance) == Rejection::None;
  }

  /// A position x of the draft solved against bodies i and j of rank 0 (a wall among them) that
  /// lies beyond a wall's face: a mesh facet or polygon edge is solved as its whole plane (line),
  /// and a position tangent to it beyond the face touches no wall there.
  bool off_face(const Draft& d, const Vec<D>& x, int i, int j, int rank) const {
    return rank == 0 && !(model_.over_face(i, d, x) && model_.over_face(j, d, x));
  }

  /// Why a candidate position x of the draft, touching s0 and bodies of the given rank, cannot be
  /// kept (None: it can): outside the block, overlapping a particle of V beyond `allowance` x the
  /// tolerance, outside the container, or not touching the wall it was solved against.
  enum class Rejection { None, Block, Overlap, Container };
  Rejection rejection(const Draft& d, const Vec<D>& x, int rank, double allowance = 1.0) {
    if (!in_block(x)) return Rejection::Block;
    if (model_.overlaps_neighbour(d, x, allowance)) return Rejection::Overlap;
    if (!model_.inside(d, x)) return Rejection::Container;
    if (rank == 0 && !model_.touches_boundary(d, x)) return Rejection::Container;
    return Rejection::None;
  }

  /// Step 2.2 for one draft: a position touching s0 and D-1 bodies of V, overlapping nothing,
  /// inside the container (the one kept by opt_.candidate). False if there is none.
  bool find_position(const Draft& d, int s0, Result& res, Found& best) {
    const double r = radius(d);
    const Vec<D> c0 = model_.position(s0);
    const double r0 = model_.radius(s0);
    const bool keep_first = opt_.candidate == CandidateChoice::First;
    bool found = false;
    // Every candidate lies within r0 + r of c0: a lower bound for its growth key.
    const double lower_bound = growth_key_bound(c0, r0 + r);

    model_.begin_placement(s0, d, bodies_);
    std::array<Placement<D>, Model::kMaxPlacements> out;
    const int nb = static_cast<int>(bodies_.size());

    // Keeping the closest candidate, a candidate that touches a wall outranks one that does
    // not: the layer against the wall is laid first, instead of being approached by particles
    // nestled closer to the seed that leave sub-particle gaps at the wall (measured in
    // experiments/front-levers: ~7x more wall contacts and a denser boundary layer).
    bool any_position = false;  // some pair had a solution (valid or not)
    // A candidate x touching s0 and bodies i and j of the given rank (0: a wall among them):
    // returns true to end the scan.
    auto test = [&](const Vec<D>& x, int i, int j, int rank) -> bool {
      ++res.counters.candidates;
      double key = 0;
      if (!keep_first) {
        key = growth_key(x);
        if (found && (rank > best.rank || (rank == best.rank && key >= best.key))) return false;
      }
      switch (rejection(d, x, rank)) {
        case Rejection::None: break;
        case Rejection::Block: ++res.counters.rejected_block; return false;
        case Rejection::Overlap: ++res.counters.rejected_overlap; return false;
        case Rejection::Container: ++res.counters.rejected_container; return false;
      }
      found = true;
      best = Found{x, i, j, rank, key};
      return keep_first || (rank == 0 && key <= lower_bound);
    };
    auto consider = [&](int i, int j) -> bool {  // returns true to end the scan
      if (time_up()) return true;
      ++res.counters.solves;
      const int m = model_.solve(i, j, std::span<Placement<D>>(out.data(), out.size()));
      const int rank = (bodies_[i].is_wall() || bodies_[j].is_wall()) ? 0 : 1;
      any_position |= m > 0;
      for (int q = 0; q < m; ++q) {
        if (off_face(d, out[q].position, i, j, rank)) {
          ++res.counters.rejected_off_face;
          continue;
        }
        if (test(out[q].position, i, j, rank)) return true;
      }
      return false;
    };
    if constexpr (D == 2) {
      for (int i = 0; i < nb; ++i) {
        ++res.counters.pairs_considered;
        if (!model_.reachable(i)) { ++res.counters.pairs_pruned; continue; }
        if (consider(i, i)) break;
      }
    } else {
      bool stop = false;
      for (int j = 1; j < nb && !stop; ++j) {
        if (!model_.reachable(j)) continue;
        for (int i = 0; i < j; ++i) {
          ++res.counters.pairs_considered;
          if (!model_.bridgeable(i, j, d)) { ++res.counters.pairs_pruned; continue; }
          if (consider(i, j)) { stop = true; break; }
        }
      }
      // No pair had any position: a container too narrow for three contacts (a needle, a
      // capillary). Positions touching s0 and one body keep the growth going along the wall.
      if constexpr (Model::kTwoContactFallback) {
        if (!any_position) {
          for (int b = 0; b < nb && !(found && keep_first); ++b) {
            two_contact_.clear();
            model_.two_contact(s0, b, d, two_contact_);
            for (const Vec<D>& x : two_contact_)
              if (test(x, b, b, bodies_[b].is_wall() ? 0 : 1)) break;
          }
          if (found) ++res.counters.two_contact_placements;
        }
      }
    }
    return found;
  }

  static constexpr std::size_t kMaxContactBodies = 64;  // particle bodies per pair scan (gather_neighbours)
  // A draft at least kWaitRatio times the smallest other waits after kWaitAfter picks without
  // room (missed()). Waiting after 4 dropped over a hundred of a continuous law's large drafts
  // (uniform radii 50 times apart: container fraction 0.577 to 0.560).
  static constexpr int kWaitAfter = 64;
  static constexpr double kWaitRatio = 3.0;
  // Waiting drafts at most (missed()): sand with gravel at 1000 : 1 in a box of 5 gravel
  // diameters left 62 out and filled the box (0.631); with 16 the pool clogged again at 0.465.
  static constexpr std::size_t kMaxWaiting = 256;
  // Drafts wait only where the large ones hold less of the law's volume than this (spheres; shapes
  // are not measured yet). Where they hold nearly all of it the small ones only fill their gaps,
  // and letting them grow ahead of the large ones fills the container with filler: radii 0.001 and
  // 0.1 at 1000 : 1 (99.9 % of the volume large) ran over 5 minutes, not 27 s. Sand with gravel
  // at 1000 : 1 and radii 10 times apart has half its volume in the gravel.
  static constexpr double kMaxLargeShare = 0.9;
  static constexpr int kShareSamples = 4096;
  // A large class rarer than this by count is placed ahead of the front (start_large_ahead): sand
  // with gravel at 1000 : 1 is; a lognormal or uniform law 50 times wide is not (a quarter to
  // nearly all of its drafts are 3 times its smallest radius or more).
  static constexpr double kRareLargeCountShare = 0.05;
  static constexpr int kLargeSamples = 256;      // large drafts sampled for their mean r^D
  static constexpr int kMaxClassDraws = 1 << 22;  // draws at most to sample them (a class rarer still)
  // start_large_ahead's lattice: spacing in the smallest large radius, points at most.
  static constexpr double kLatticeSpacing = 0.25;
  static constexpr double kLatticePoints = double(1 << 22);
  static constexpr std::uint64_t kLargeStreamSalt = 0x6a09e667f3bcc909ULL;
  // place_fines: skeleton grains and points on them tried per grain of sand; the clock's period.
  static constexpr int kFineTries = 64;
  static constexpr std::uint64_t kFinesClockEvery = 256;
  static constexpr std::uint64_t kShareSampleSeed = 0x5eed;
  // The roll's turn angles (radians): the first, the largest and the smallest tried.
  static constexpr double kRollAngle = 0.3, kMaxRollAngle = 1.0, kMinRollAngle = 1e-3;
  static constexpr double kRollAllowance = 0.1;  // the roll's overlap allowance, in the scan's

  const Container<D>& container_;
  PackerOptions opt_;
  StopCriteria stop_;
  Rng rng_;
  const Block* block_;  // null: the whole container
  Model model_;
  Vec<D> seed_point_;
  bool probe_smallest_ = false;
  double measure_ = 0;  // container volume (area), cached: a mesh computes it from its facets

  std::priority_queue<FrontEntry> heap_;
  std::vector<int> list_;
  std::size_t fifo_head_ = 0;
  std::chrono::steady_clock::time_point started_;  ///< when run() began (time_up)
  std::vector<Draft> pool_;
  std::vector<int> misses_;  // per pooled draft: picks at which it found no room (waiting())
  std::size_t waiting_count_ = 0;  // pooled drafts waiting
  bool may_wait_ = false;          // drafts may wait (the constructor: the law, the kind of particle)
  // A rare large class placed ahead of the front (start_large_ahead; empty lattice_: not).
  std::optional<ClosingLattice<D>> lattice_;
  double large_threshold_ = std::numeric_limits<double>::infinity();  // large: radius at least this
  double large_volume_share_ = 0;   // the law's share of its volume (sum of r^D) in large drafts
  double large_mean_rD_ = 0;        // the mean r^D of a large draft
  double placed_rD_ = 0, large_rD_ = 0;  // sums of r^D placed: every particle, the large ones
  std::vector<Draft> large_pending_;  // large drafts drawn, not placed yet
  std::size_t large_drawn_ahead_ = 0;  // drawn before their turn, not yet skipped in return by draw()
  Rng large_rng_;                      // the large drafts drawn before their turn
  // A skeleton of the large class first, the fines on it (place_fines).
  bool skeleton_first_ = false;
  std::vector<Draft> fines_;                      // the small drafts drawn, in the law's order
  std::vector<std::size_t> fines_before_large_;   // per large draft drawn: the fines drawn before it
  std::size_t fines_next_ = 0;                    // the next fine to place
  std::size_t fines_failed_ = 0;                  // fines that found no room
  std::vector<int> order_;
  std::vector<double> failed_radius_;  // per particle: smallest pooled radius that failed there
  std::vector<Neighbour> nb_;
  std::vector<Wall<D>> walls_;
  std::vector<Body<D>> bodies_;
  std::vector<Vec<D>> two_contact_;  // scratch: positions touching s0 and one body (3D fallback)
  std::vector<char> in_front_;  // per particle: still in F
  // Lattice points of resume_at_voids() already reopened, per lattice spacing.
  std::map<double, std::unordered_set<std::int64_t>> voids_reopened_;
};

}  // namespace fp
