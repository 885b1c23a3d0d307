// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Boundary_lipschitz_sizing_2: the largest k-Lipschitz sizing field bounded by sizes on the
// boundary.
#ifndef CVT_2_BOUNDARY_LIPSCHITZ_SIZING_2_H
#define CVT_2_BOUNDARY_LIPSCHITZ_SIZING_2_H

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_2.h>
#include <CVT_2/Concepts/BvdFaceBase_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/layout/double_pair.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/mark_domain_2.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Policies
/// The automatic sizing field of the paper's Section 4, after [ACSYD05]:
/// \f[ \mu(x) = \min_{s \in \partial\Omega} \big(k\, d(x, s) + \mathrm{size}(s)\big), \f]
/// the largest \f$k\f$-Lipschitz function that is at most \f$\mathrm{size}(s)\f$ on every
/// boundary segment \f$s\f$. Cells are small near the boundary (and near inner constraints) and
/// grow by \f$k\f$ per unit of distance away from it; the paper uses \f$k = 0.1\f$. Wrap it in
/// `Sizing_field_density_2` to get the density of the Lloyd iteration.
///
/// \f$\mathrm{size}(s)\f$ is either one constant for all segments or, by default, the length of
/// \f$s\f$ (the local boundary edge length), so that the cells near the boundary match its
/// sampling.
///
/// An evaluation does not scan the boundary: the segments sit in a CGAL AABB tree (3D in CGAL
/// 5.5, so each segment is lifted to the height \f$z = \mathrm{size}(s)\f$) and a branch and
/// bound walk skips every box whose lower bound
/// \f$k\, d_{xy}(x, \mathrm{box}) + z_{\min}(\mathrm{box})\f$ already reaches the best value
/// found. The candidates it keeps are evaluated exactly as in the formula, so the result
/// equals the minimum over all segments up to rounding. With `double` coordinates the segments
/// are also kept flat, as the many evaluations of a cell read them.
///
/// Copies share the tree and are cheap; the call operator changes nothing and may run in
/// several threads at once.
///
/// \tparam K a CGAL kernel with 3D types (any CGAL kernel) whose `FT` has a square root
///         (`CGAL::Exact_predicates_inexact_constructions_kernel`, for example).
/// \cgalModels `SizingField_2`
/// \sa `Sizing_field_density_2`
template <class K>
class Boundary_lipschitz_sizing_2 {
  struct Data;

  // Tells the triangulation constructor from the segment range one.
  template <class T, class = void>
  struct Is_triangulation : std::false_type {};
  template <class T>
  struct Is_triangulation<T, std::void_t<decltype(std::declval<const T&>().is_constrained(
                                 std::declval<const typename T::Edge&>()))>> : std::true_type {};

 public:
  using Geom_traits = K;                    ///< the kernel
  using FT = typename K::FT;                ///< the number type
  using Point_2 = typename K::Point_2;      ///< the point type
  using Segment_2 = typename K::Segment_2;  ///< a boundary segment

  static_assert(
      !std::is_same<typename CGAL::Algebraic_structure_traits<FT>::Sqrt, CGAL::Null_functor>::value,
      "Boundary_lipschitz_sizing_2<K>: K::FT must have a square root (CGAL::sqrt)");

  /// The sizing field of the boundary of the domain of `cdt`: every constrained edge that
  /// borders at least one face of the domain (`is_inside_domain()`), so the outer boundary, the
  /// holes' boundaries and the inner constraints.
  ///
  /// Each edge of the triangulation is a segment: a constraint split by a vertex inserted on it
  /// gives two shorter segments, hence smaller default sizes. Build the field from the input
  /// domain, before generators are inserted.
  /// \tparam CDT a `CGAL::Constrained_triangulation_2` or a derived class, whose faces model
  ///         `BvdFaceBase_2`, with its domain marked by `mark_domain_2()`.
  /// \param cdt the triangulation.
  /// \param k the Lipschitz constant \f$k\f$.
  /// \param size the size of every segment; by default (`std::nullopt`) each segment's length.
  /// \throws std::invalid_argument if `k` or `size` is not positive and finite.
  /// \throws Domain_error if no constrained edge borders the domain, or if a segment has a
  ///         coordinate that is not finite, or has length 0 and no `size` is given.
  template <class CDT, std::enable_if_t<Is_triangulation<CDT>::value, int> = 0>
  Boundary_lipschitz_sizing_2(const CDT& cdt, const FT& k, std::optional<FT> size = std::nullopt) {
    static_assert(is_bvd_face_base_2<typename CDT::Face>::value,
                  "CDT::Face must model BvdFaceBase_2: bool is_inside_domain() const, "
                  "void set_inside_domain(bool), bool is_blinded() const, "
                  "Edge blinding_edge() const, void set_blinding_edge(const Edge&), "
                  "void clear_blinding()");
    // The triangulation's edge iterator visits an edge from the face of smaller address: the
    // segments are oriented and ordered by their points instead, so that the field (whose
    // distances round differently for a segment and its reverse) does not depend on where the
    // faces lie in memory.
    std::vector<Segment_2> segments;
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
      if (!cdt.is_constrained(*e)) continue;
      const auto f = e->first, g = f->neighbor(e->second);
      if ((!cdt.is_infinite(f) && f->is_inside_domain()) ||
          (!cdt.is_infinite(g) && g->is_inside_domain())) {
        const Segment_2 s = cdt.segment(*e);
        segments.push_back(s.source() < s.target() ? s : s.opposite());
      }
    }
    std::sort(segments.begin(), segments.end(), [](const Segment_2& a, const Segment_2& b) {
      return a.source() < b.source() || (a.source() == b.source() && a.target() < b.target());
    });
    initialize(std::move(segments), k, size);
  }

  /// The sizing field of the segments of `segments`, which need not form a closed boundary.
  /// \tparam SegmentRange a range whose values convert to `Segment_2`.
  /// \param segments the segments \f$s\f$; a segment of length 0 acts as a point.
  /// \param k the Lipschitz constant \f$k\f$.
  /// \param size the size of every segment; by default (`std::nullopt`) each segment's length.
  /// \throws std::invalid_argument if `k` or `size` is not positive and finite.
  /// \throws Domain_error if `segments` is empty, or if a segment has a coordinate that is not
  ///         finite, or has length 0 and no `size` is given; `Domain_error::index()` then gives
  ///         its position.
  template <class SegmentRange, std::enable_if_t<!Is_triangulation<SegmentRange>::value, int> = 0>
  Boundary_lipschitz_sizing_2(const SegmentRange& segments, const FT& k,
                              std::optional<FT> size = std::nullopt) {
    std::vector<Segment_2> s;
    for (const auto& x : segments) s.push_back(x);
    initialize(std::move(s), k, size);
  }

  /// The field restricted to a disk (see `restrict_to_disk()`): a model of `SizingField_2` that
  /// evaluates only the few segments that can be the minimizing one there.
  class Restriction {
   public:
    /// \f$\min_s (k\, d(x, s) + \mathrm{size}(s))\f$ over the kept segments. They are
    /// visited by their value at the disk's center: a segment's value at x is at least that
    /// minus \f$k |x - c|\f$, so once that bound exceeds the least value found, with a margin
    /// for rounding, no later segment can give less and the walk stops; a segment whose bound
    /// by its slope (below) exceeds it is skipped (the same bits).
    FT operator()(const Point_2& x) const {
      const double dx = CGAL::to_double(x.x()) - m_cx, dy = CGAL::to_double(x.y()) - m_cy;
      const double reach = m_k * std::sqrt(dx * dx + dy * dy);
      std::optional<FT> best;
      double bound = std::numeric_limits<double>::infinity();
      for (const Candidate& c : m_candidates) {
        if (c.at_center - reach > bound) break;
        if (c.at_center + c.slope_x * dx + c.slope_y * dy - c.slope_error * reach > bound) continue;
        const FT v = value(*m_data, x, c.segment);
        if (!best || v < *best) {
          best = v;
          const double b = CGAL::to_double(v);
          bound = b + 1e-12 * (std::abs(b) + c.at_center + reach + m_scale) + m_data->rounding;
        }
      }
      return best ? *best : FT(std::numeric_limits<double>::quiet_NaN());
    }
    /// The field at each of `points` into `values` (replaced), bit for bit what the call
    /// operator gives at finite points: each kept segment at all the points in turn, without
    /// the call operator's bounds and their branches, which mispredict as the nearest segment
    /// changes from point to point among a cell's quadrature points (see
    /// `SizingField_2::evaluate()`). The same bounds skip whole segments instead: one that
    /// cannot beat the least value found at any of the points.
    void evaluate(const std::vector<Point_2>& points, std::vector<FT>& values) const {
      if constexpr (!is_double) {
        values.clear();
        for (const Point_2& p : points) values.push_back((*this)(p));
      } else if (m_candidates.empty()) {
        values.assign(points.size(), std::numeric_limits<double>::quiet_NaN());
      } else {
        // two points at a time: the coordinates apart, the last repeated to an even count
        const std::size_t n = points.size(), count = n + n % 2;
        thread_local std::vector<double> xs, ys, least;
        xs.resize(count);
        ys.resize(count);
        double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
        double times_zero = 0;  // NaN if a coordinate is not finite
        for (std::size_t i = 0; i < count; ++i) {
          const Point_2& p = points[std::min(i, n - 1)];
          xs[i] = p.x(), ys[i] = p.y();
          x0 = std::min(x0, xs[i]), x1 = std::max(x1, xs[i]);
          y0 = std::min(y0, ys[i]), y1 = std::max(y1, ys[i]);
          times_zero += xs[i] * 0 + ys[i] * 0;
        }
        // Skipping needs every value finite: the minimum and maximum of pairs drop NaNs.
        const bool skips = times_zero == 0;
        // the points' box about the center, and k times the distance to its farthest corner
        x0 -= m_cx, x1 -= m_cx, y0 -= m_cy, y1 -= m_cy;
        const double fx = std::max(-x0, x1), fy = std::max(-y0, y1);
        const double reach = m_k * std::sqrt(fx * fx + fy * fy);
        least.assign(count, std::numeric_limits<double>::infinity());
        const Points batch{xs.data(), ys.data(), least.data(), count};
        double most = std::numeric_limits<double>::infinity();  // the largest least value
        for (const Candidate& c : m_candidates) {
          // The call operator's bounds with what holds at all the points: the farthest
          // reach and the largest least value (bound, with its margin for rounding).
          const double bound =
              most + 1e-12 * (most + c.at_center + reach + m_scale) + m_data->rounding;
          if (skips) {
            if (c.at_center - reach > bound) break;  // and so would every later segment
            const double low_on_box = c.at_center + std::min(c.slope_x * x0, c.slope_x * x1) +
                                      std::min(c.slope_y * y0, c.slope_y * y1) -
                                      c.slope_error * reach;
            if (low_on_box > bound) continue;
            if (most < std::numeric_limits<double>::infinity() &&
                !beats_somewhere(c, batch, bound - most, reach))
              continue;
          }
          most = lower_least(c, batch);
        }
        values.assign(least.begin(), least.begin() + n);
      }
    }
    /// the number of segments kept
    std::size_t number_of_segments() const { return m_candidates.size(); }

   private:
    friend class Boundary_lipschitz_sizing_2;
    explicit Restriction(const Data& d, const Point_2& center)
        : m_data(&d),
          m_cx(CGAL::to_double(center.x())),
          m_cy(CGAL::to_double(center.y())),
          m_k(CGAL::to_double(d.k)),
          m_scale(m_k * (std::abs(m_cx) + std::abs(m_cy))) {}
    // A kept segment s: its value v at the center c and its slope there, k times the unit
    // vector g from the point of s nearest c. The distance to a segment is convex, so its
    // value at x is at least v + k g.(x - c): a second bound, tighter than v - k|x - c| across
    // g, that spares the distance of most segments that cannot beat the best value. g is
    // rounded: slope_error (times k|x - c|) covers it; 1 when c is too near s for g to mean
    // anything (the bound is then v - k|x - c|).
    struct Candidate {
      double at_center, slope_x, slope_y, slope_error;
      std::size_t segment;
      bool operator<(const Candidate& o) const {
        return at_center < o.at_center || (at_center == o.at_center && segment < o.segment);
      }
    };
    // A batch's points and their least values so far, `count` (even) of each.
    struct Points {
      const double *x, *y;
      double* least;
      std::size_t count;
    };
    // Whether the slope bound of c (its value at x is at least v + k g.(x - c), less the
    // rounding of g) falls within `margin` of the least value at one of the points at least.
    bool beats_somewhere(const Candidate& c, const Points& p, double margin, double reach) const {
      const auto gx = Pair::all(c.slope_x), gy = Pair::all(c.slope_y);
      auto low = Pair::all(std::numeric_limits<double>::infinity());
      for (std::size_t i = 0; i < p.count; i += 2) {
        const auto slope =
            Pair::add(Pair::mul(gx, Pair::load(p.x + i)), Pair::mul(gy, Pair::load(p.y + i)));
        low = Pair::min(low, Pair::sub(slope, Pair::load(p.least + i)));
      }
      return internal::least_lane(low) <=
             margin - c.at_center + c.slope_x * m_cx + c.slope_y * m_cy + c.slope_error * reach;
    }
    // The least values lowered by c's, all computed by flat_values(); returns the largest.
    double lower_least(const Candidate& c, const Points& p) const {
      const Lanes s(m_data->flat[c.segment], m_data->k);
      auto top = Pair::all(-std::numeric_limits<double>::infinity());
      for (std::size_t i = 0; i < p.count; i += 2) {
        const auto v = Pair::min(Pair::load(p.least + i),
                                 flat_values(s, Pair::load(p.x + i), Pair::load(p.y + i)));
        Pair::store(p.least + i, v);
        top = Pair::max(top, v);
      }
      return internal::greatest_lane(top);
    }
    void add(double at_center, std::size_t i) {
      Candidate c{at_center, 0, 0, 1, i};
      const auto [px, py, extent] = nearest_point(*m_data, m_cx, m_cy, i);
      const double gx = m_cx - px, gy = m_cy - py, d = std::sqrt(gx * gx + gy * gy);
      // the rounding of c - p, relative to its length
      const double error = 1e-14 * (extent + std::abs(m_cx) + std::abs(m_cy)) / d;
      if (d > 0 && error < 1) c = {at_center, m_k * gx / d, m_k * gy / d, error, i};
      m_candidates.push_back(c);
    }
    // Keeps, after sorting, the first segment b and those that can beat it somewhere within
    // `radius`: by the bound above and b's value there, at most
    // v_b + k g_b.(x - c) + k |x - c|^2 / (2 (d_b - radius)) (the distance to a segment curves
    // by at most 1/d, and d >= d_b - radius on the disk), s beats b only if
    // v_s - v_b <= radius |k g_s - k g_b| + k radius^2 / (2 (d_b - radius)), plus the slopes'
    // rounding. Along a finely cut curve this keeps the segments near the center's foot, not
    // all those within 2 k radius.
    void keep_competitors(double radius, double slack) {
      std::sort(m_candidates.begin(), m_candidates.end());
      if (m_candidates.size() < 2) return;
      const Candidate b = m_candidates.front();
      const double reach = m_k * radius;
      const double d_b = std::sqrt(std::max(0.0, nearest_squared_distance(b.segment)));
      const double curving = d_b > radius ? reach * radius / (2 * (d_b - radius))
                                          : std::numeric_limits<double>::infinity();
      const auto cannot_beat = [&](const Candidate& c) {
        const double sx = c.slope_x - b.slope_x, sy = c.slope_y - b.slope_y;
        const double gain = std::min(2 * reach, radius * std::sqrt(sx * sx + sy * sy) + curving +
                                                    (c.slope_error + b.slope_error) * reach);
        return c.at_center - b.at_center > gain + slack;
      };
      m_candidates.erase(std::remove_if(m_candidates.begin() + 1, m_candidates.end(), cannot_beat),
                         m_candidates.end());
    }
    double nearest_squared_distance(std::size_t i) const {
      const auto [px, py, extent] = nearest_point(*m_data, m_cx, m_cy, i);
      (void)extent;
      return (m_cx - px) * (m_cx - px) + (m_cy - py) * (m_cy - py);
    }
    const Data* m_data;
    double m_cx, m_cy, m_k, m_scale;      // m_scale: k times the center's size, for rounding
    std::vector<Candidate> m_candidates;  // by value at the center
  };

  /// \f$\mu(x) = \min_s (k\, d(x, s) + \mathrm{size}(s))\f$.
  /// \pre `x` has finite coordinates; otherwise the result is NaN or infinite, which
  ///      `Sizing_field_density_2` reports.
  FT operator()(const Point_2& x) const {
    Search search(*m_data, x);
    m_data->tree.traversal_with_priority(x, search);
    return search.best ? *search.best : FT(std::numeric_limits<double>::quiet_NaN());
  }

  /// The field near `center`, where few segments can be the minimizing one.
  ///
  /// The call operator of the result equals this one, bit for bit, at every point \f$y\f$ with
  /// \f$|y - c| \le r\f$ (\f$c\f$ = `center`, \f$r\f$ = `radius`), and costs a few segment
  /// distances instead of a walk of the tree. Since \f$\mu\f$ is \f$k\f$-Lipschitz, a segment
  /// \f$s\f$ with \f$k\,d(c, s) + \mathrm{size}(s) > \mu(c) + 2kr\f$ is beaten at every such
  /// \f$y\f$ by the segment \f$b\f$ that gives \f$\mu(c)\f$ (one walk of the tree finds the
  /// others). Of those, it keeps the ones that can beat \f$b\f$ by their slopes at \f$c\f$ too:
  /// the distance to a segment is convex and curves by at most \f$1/d\f$, so along a finely cut
  /// curve, where many segments nearly tie, only those whose nearest points lie near that of
  /// \f$b\f$ remain. The Lloyd optimizer restricts the field to a disk around each generator
  /// that holds its cell, so the many quadrature points of a cell cost about one query, and
  /// keeps the restriction while the cell stays in the disk.
  /// \pre `center` and `radius` are finite, `radius` \f$\ge 0\f$. The result refers to this
  /// field's data, which must outlive it.
  Restriction restrict_to_disk(const Point_2& center, const FT& radius) const {
    Collect collect(*m_data, center, 2 * CGAL::to_double(m_data->k * radius));
    m_data->tree.traversal_with_priority(center, collect);
    Restriction r(*m_data, center);
    r.m_candidates.reserve(collect.candidates.size());
    for (const auto& [value, i] : collect.candidates)
      if (value <= collect.best_double + collect.slack) r.add(value + collect.margin, i);
    r.keep_competitors(CGAL::to_double(radius), collect.slack);
    return r;
  }

  FT lipschitz_constant() const { return m_data->k; }  ///< \f$k\f$
  /// the boundary segments, in the order of the input; from a triangulation, each from its
  /// lexicographically smaller end, in lexicographic order
  const std::vector<Segment_2>& segments() const { return m_data->segments; }
  /// \f$\mathrm{size}(s)\f$ of each segment, in the order of `segments()`
  const std::vector<FT>& sizes() const { return m_data->sizes; }

 private:
  using Segment_3 = typename K::Segment_3;
  using Segment_3_iterator = typename std::vector<Segment_3>::const_iterator;
  using Primitive = CGAL::AABB_segment_primitive<K, Segment_3_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

  // A segment as its value is computed: its ends a and b, the unit vector w along b - a (0 for
  // a point), |b - a|, its size.
  struct Flat_segment {
    double ax, ay, bx, by, wx, wy, length, size;
  };

  // Never moved once built: the tree's primitives point into `lifted`.
  struct Data {
    FT k;
    std::vector<Segment_2> segments;
    std::vector<FT> sizes;
    std::vector<Flat_segment> flat;  // with double coordinates only
    // A value rounds by a few ulps of k times the coordinates of x and of its segment: the
    // margin, 1e-12 k times the largest extent(), that every comparison of values and bounds
    // adds, so that long segments far from x do not tip a near tie.
    double rounding = 0;
    std::vector<Segment_3> lifted;  // segment i at the height sizes[i]
    Tree tree;
  };

  static constexpr bool is_double = std::is_same<FT, double>::value;

  // The value of segment i at x: all evaluations of one point go through here, so a
  // restriction gives the same bits as the whole tree; with double coordinates by
  // flat_values(), from the segment's numbers laid out flat.
  static FT value(const Data& data, const Point_2& x, std::size_t i) {
    if constexpr (is_double) {
      return flat_value(data.flat[i], data.k, x.x(), x.y());
    } else {
      return data.k * CGAL::sqrt(CGAL::squared_distance(x, data.segments[i])) + data.sizes[i];
    }
  }

  using Pair = internal::Double_pair;

  // A flat segment in both lanes of pairs, with k.
  struct Lanes {
    typename Pair::type ax, ay, bx, by, wx, wy, length, size, k;
    Lanes(const Flat_segment& s, double lipschitz)
        : ax(Pair::all(s.ax)),
          ay(Pair::all(s.ay)),
          bx(Pair::all(s.bx)),
          by(Pair::all(s.by)),
          wx(Pair::all(s.wx)),
          wy(Pair::all(s.wy)),
          length(Pair::all(s.length)),
          size(Pair::all(s.size)),
          k(Pair::all(lipschitz)) {}
  };

  // The values of s at two points (x, y) with double coordinates. Every value of the field goes
  // through here, one point in both lanes or two, so all have the same bits: the squared
  // distance to the end nearer x when its projection falls outside, else the cross product with
  // the unit direction, squared (CGAL divides by the supporting line's coefficients instead:
  // other rounding); each case computed and the right one selected, without branches or
  // divisions, which share the divider with the square root.
  static typename Pair::type flat_values(const Lanes& s, typename Pair::type x,
                                         typename Pair::type y) {
    using P = Pair;
    const auto dx = P::sub(x, s.ax), dy = P::sub(y, s.ay);
    const auto along = P::add(P::mul(dx, s.wx), P::mul(dy, s.wy));
    const auto ex = P::sub(x, s.bx), ey = P::sub(y, s.by);
    const auto cross = P::sub(P::mul(s.wx, dy), P::mul(s.wy, dx));
    const auto to_a = P::add(P::mul(dx, dx), P::mul(dy, dy));
    const auto to_b = P::add(P::mul(ex, ex), P::mul(ey, ey));
    const auto d2 = P::select(along, s.length, to_a, to_b, P::mul(cross, cross));
    return P::add(P::mul(s.k, P::sqrt(d2)), s.size);
  }
  static double flat_value(const Flat_segment& s, double k, double x, double y) {
    return Pair::first(flat_values(Lanes(s, k), Pair::all(x), Pair::all(y)));
  }

  // The size of the numbers a value of s is computed from, |a_x| + |a_y| + |b_x - a_x| +
  // |b_y - a_y| in doubles: its rounding is relative to that.
  static double extent(const Segment_2& s) {
    const double ax = CGAL::to_double(s.source().x()), ay = CGAL::to_double(s.source().y());
    return std::abs(ax) + std::abs(ay) + std::abs(CGAL::to_double(s.target().x()) - ax) +
           std::abs(CGAL::to_double(s.target().y()) - ay);
  }

  // The point of segment i nearest (x, y), in doubles, and the segment's extent.
  static std::array<double, 3> nearest_point(const Data& data, double x, double y, std::size_t i) {
    const Segment_2& s = data.segments[i];
    const double ax = CGAL::to_double(s.source().x()), ay = CGAL::to_double(s.source().y());
    const double ux = CGAL::to_double(s.target().x()) - ax;
    const double uy = CGAL::to_double(s.target().y()) - ay;
    const double length2 = ux * ux + uy * uy;
    const double along = length2 > 0 ? ((x - ax) * ux + (y - ay) * uy) / length2 : 0;
    const double t = std::clamp(along, 0.0, 1.0);
    return {ax + t * ux, ay + t * uy, extent(s)};
  }

  // The branch and bound walk of the tree, nearer boxes first (CGAL's priority traversal,
  // which its ray queries use). A box cannot beat `best` if k d_xy(x, box) + z_min >= best:
  // each segment in it has d(x, s) >= d_xy(x, box) and size(s) >= z_min.
  struct Search {
    using Priority = double;
    const Data& data;
    const Point_2& x;
    const double xd, yd, k;
    std::optional<FT> best;  // none until a segment is evaluated
    double best_double = std::numeric_limits<double>::infinity();
    // A bound and a value are both rounded: a box is skipped only when its bound beats the best
    // value by more than rounding, so the segments that tie with the minimum are all seen and the
    // result is the minimum of the formula over all segments, whatever the walk.
    static constexpr double tolerance = 1 + 1e-12;

    Search(const Data& d, const Point_2& p)
        : data(d),
          x(p),
          xd(CGAL::to_double(p.x())),
          yd(CGAL::to_double(p.y())),
          k(CGAL::to_double(d.k)) {}

    bool go_further() const { return true; }
    void intersection(const Point_2&, const Primitive& primitive) {
      const std::size_t i = static_cast<std::size_t>(primitive.id() - data.lifted.begin());
      const FT v = value(data, x, i);
      if (!best || v < *best) {
        best = v;
        best_double = CGAL::to_double(v);
      }
    }
    double lower_bound(const CGAL::Bbox_3& b) const {
      const double dx = std::max({b.xmin() - xd, 0.0, xd - b.xmax()});
      const double dy = std::max({b.ymin() - yd, 0.0, yd - b.ymax()});
      return k * std::sqrt(dx * dx + dy * dy) + b.zmin();
    }
    template <class Node>
    bool do_intersect(const Point_2&, const Node& node) const {
      return lower_bound(node.bbox()) <= best_double * tolerance + data.rounding;
    }
    template <class Node>
    std::pair<bool, Priority> do_intersect_with_priority(const Point_2&, const Node& node) const {
      const double b = lower_bound(node.bbox());
      return {b <= best_double * tolerance + data.rounding, -b};
    }
  };

  // The same walk with the bound raised by `margin` = 2kr: it keeps every segment whose value
  // at x may come within the margin of the minimum (a superset: the bound only falls).
  struct Collect : Search {
    double margin, slack;
    boost::container::small_vector<std::pair<double, std::size_t>, 16> candidates;

    Collect(const Data& d, const Point_2& p, double m)
        : Search(d, p),
          margin(m),
          // rounding of the values and bounds, and of quadrature points near the disk's edge
          slack(m * 1e-6 + 1e-12 * (std::abs(this->xd) + std::abs(this->yd) + m) + 2 * d.rounding) {
    }

    void intersection(const Point_2& p, const Primitive& primitive) {
      const std::size_t i = static_cast<std::size_t>(primitive.id() - this->data.lifted.begin());
      const FT v = value(this->data, this->x, i);
      if (!this->best || v < *this->best) {
        this->best = v;
        this->best_double = CGAL::to_double(v);
      }
      (void)p;
      if (CGAL::to_double(v) <= this->best_double + margin + slack)
        candidates.emplace_back(CGAL::to_double(v) - margin, i);
    }
    template <class Node>
    bool do_intersect(const Point_2&, const Node& node) const {
      return this->lower_bound(node.bbox()) <= this->best_double + margin + slack;
    }
    template <class Node>
    std::pair<bool, double> do_intersect_with_priority(const Point_2&, const Node& node) const {
      const double b = this->lower_bound(node.bbox());
      return {b <= this->best_double + margin + slack, -b};
    }
  };

  static bool is_positive_finite(const FT& x) { return x > 0 && std::isfinite(CGAL::to_double(x)); }

  void initialize(std::vector<Segment_2> segments, const FT& k, const std::optional<FT>& size) {
    if (!is_positive_finite(k))
      throw std::invalid_argument("Boundary_lipschitz_sizing_2: k = " +
                                  internal::number_to_string(k) + " must be positive and finite");
    if (size && !is_positive_finite(*size))
      throw std::invalid_argument(
          "Boundary_lipschitz_sizing_2: size = " + internal::number_to_string(*size) +
          " must be positive and finite");
    if (segments.empty()) throw Domain_error("Boundary_lipschitz_sizing_2: no boundary segment");
    auto data = std::make_shared<Data>();
    data->k = k;
    data->sizes.reserve(segments.size());
    data->lifted.reserve(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Segment_2& s = segments[i];
      const auto where = [&s] {
        return "Boundary_lipschitz_sizing_2: segment " + internal::to_string(s.source()) + " - " +
               internal::to_string(s.target());
      };
      if (!internal::is_valid_point(s.source()) || !internal::is_valid_point(s.target()))
        throw Domain_error(internal::invalid_point_message(where()), i);
      const FT si = size ? *size : CGAL::sqrt(s.squared_length());
      if (!is_positive_finite(si))
        throw Domain_error(where() + " has length " + internal::number_to_string(si) +
                               ": its size must be positive and finite",
                           i);
      data->sizes.push_back(si);
      data->lifted.emplace_back(typename K::Point_3(s.source().x(), s.source().y(), si),
                                typename K::Point_3(s.target().x(), s.target().y(), si));
      if constexpr (is_double) {
        const double ux = s.target().x() - s.source().x(), uy = s.target().y() - s.source().y();
        const double length = std::hypot(ux, uy);
        const double wx = length > 0 ? ux / length : 0, wy = length > 0 ? uy / length : 0;
        data->flat.push_back(
            {s.source().x(), s.source().y(), s.target().x(), s.target().y(), wx, wy, length, si});
      }
      data->rounding = std::max(data->rounding, extent(s));
    }
    data->rounding *= 1e-12 * CGAL::to_double(k);
    data->segments = std::move(segments);
    data->tree.insert(data->lifted.begin(), data->lifted.end());
    // The tree builds itself at its first query unless built now; built, it is read-only, so
    // concurrent const calls are safe. The walk needs no KD-tree of hints.
    data->tree.do_not_accelerate_distance_queries();
    data->tree.build();
    m_data = std::move(data);
  }

  std::shared_ptr<const Data> m_data;
};

}  // namespace CVT_2

#endif  // CVT_2_BOUNDARY_LIPSCHITZ_SIZING_2_H
