// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Sliding_runs_2: the runs of resampled constraints, along whose input polylines their vertices
// slide while an optimizer moves the free generators (`--boundary slide`); Slid_vertices_2:
// where they were, for lines named by their ends.
#ifndef CVT_2_SLIDING_RUNS_2_H
#define CVT_2_SLIDING_RUNS_2_H

#include <CVT_2/internal/delaunay_flips.h>
#include <CVT_2/internal/move_vertex.h>
#include <CVT_2/internal/to_string.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// The vertices of resampled constraints that slide along the input polylines during Lloyd
/// iteration and L-BFGS. A *run* is a piece of an input polyline between
/// two features (junctions, ends, corners, fixed points), which stay; the vertices between them
/// are points on it, joined by the chords that are the triangulation's constraints.
/// `resample_constraints_2(cdt, h, sliding_runs(&runs))` fills it; `lloyd_optimize_2()` and
/// `lbfgs_optimize_2()` with `sliding_runs(&runs)` move its vertices and keep it current.
///
/// A step moves each sliding vertex to its *constrained centroid*: the point of its run nearest
/// to the centroid of its cell, no farther than 45% of the way to either neighbour on the run
/// (so that neighbours never pass each other), where its two chords stay within
/// `deviation_bound()` of the input vertices between their ends and the triangulation stays
/// valid with it there (every face around it positive, the convex hull convex), else half as
/// far, up to eight times, else not at all; its move ratio is to that point. (So a vertex of the
/// convex hull does not leave it, and a vertex inside does not join it.) Then Lawson's flips
/// restore the constrained Delaunay property. A slid vertex is computed on its input segment in
/// double precision: on the input polyline to rounding. On a straight run the domain does not
/// change and the energy never rises; on a curved one the chords move with the vertices and so
/// does the domain, by at most the bound.
///
/// \tparam CDT a constrained Delaunay triangulation whose faces model `BvdFaceBase_2`.
template <class CDT>
class Sliding_runs_2 {
 public:
  using Point_2 = typename CDT::Point_2;              ///< point type
  using Vertex_handle = typename CDT::Vertex_handle;  ///< a vertex of the triangulation

  /// Adds a run: the input polyline `polyline` (at least two points) and the vertices on it in
  /// order, `vertices[k]` at arc length `at[k]` from its start; the first and the last, at its
  /// two ends, are features and stay (the same vertex for a ring with no feature), the others
  /// slide. \throws std::invalid_argument if the sizes differ, the arc lengths do not increase
  /// from 0 to the polyline's length, or a sliding vertex is already in a run.
  void add_run(std::vector<Point_2> polyline, std::vector<Vertex_handle> vertices,
               std::vector<double> at) {
    if (polyline.size() < 2 || vertices.size() < 2 || vertices.size() != at.size())
      throw std::invalid_argument(
          "Sliding_runs_2::add_run: a run needs a polyline of two points or more and as many arc "
          "lengths as vertices, at least two");
    Run r{std::move(polyline), {}, std::move(vertices), std::move(at), {}};
    r.length = arc_lengths(r.p);
    for (const Vertex_handle v : r.v) r.q.push_back(v->point());
    const bool increasing = std::is_sorted(r.at.begin(), r.at.end()) &&
                            std::adjacent_find(r.at.begin(), r.at.end()) == r.at.end();
    if (!increasing || r.at.front() != 0 || r.at.back() != r.length.back())
      throw std::invalid_argument(
          "Sliding_runs_2::add_run: the arc lengths must increase from 0 to the polyline's "
          "length " +
          internal::number_to_string(r.length.back()));
    const std::size_t run = m_runs.size();
    for (std::size_t k = 1; k + 1 < r.v.size(); ++k) {
      if (!m_slider_of.emplace(r.v[k], m_sliders.size()).second)
        throw std::invalid_argument("Sliding_runs_2::add_run: the vertex at " +
                                    internal::to_string(r.v[k]->point()) +
                                    " already slides on a run");
      m_sliders.push_back({run, k});
    }
    m_runs.push_back(std::move(r));
  }

  /// How far a chord may leave the input vertices between its ends (default: no bound).
  void set_deviation_bound(double d) { m_bound = d; }
  double deviation_bound() const { return m_bound; }  ///< as set

  std::size_t number_of_runs() const { return m_runs.size(); }  ///< runs added
  /// the vertices that slide (all those of the runs but their ends)
  std::size_t number_of_sliding_vertices() const { return m_sliders.size(); }
  bool empty() const { return m_sliders.empty(); }  ///< whether no vertex slides

  /// The largest distance from an input vertex to the chord over it, now (by the points the
  /// runs last saw their vertices at).
  double max_deviation() const {
    double worst = 0;
    for (const Run& r : m_runs)
      for (std::size_t k = 0; k + 1 < r.v.size(); ++k)
        worst = std::max(worst, chord_deviation2(r, r.at[k], r.q[k], r.at[k + 1], r.q[k + 1]));
    return std::sqrt(worst);
  }

  /// Finds the runs' vertices again in `cdt`, by their points as the runs last saw them: after
  /// the triangulation they were in was copied or rebuilt with the same points (it may be gone).
  /// \throws std::invalid_argument naming a point that is not a vertex of `cdt`.
  void relocate(const CDT& cdt) {
    typename CDT::Face_handle hint;
    const auto find = [&](const Point_2& p) {
      typename CDT::Locate_type lt;
      int li = 0;
      hint = cdt.locate(p, lt, li, hint);
      if (lt != CDT::VERTEX)
        throw std::invalid_argument("Sliding_runs_2::relocate: " + internal::to_string(p) +
                                    " is not a vertex of the triangulation");
      return hint->vertex(li);
    };
    std::vector<std::vector<Vertex_handle>> found;
    for (const Run& r : m_runs) {
      found.emplace_back();
      for (const Point_2& p : r.q) found.back().push_back(find(p));
    }
    for (std::size_t i = 0; i < m_runs.size(); ++i) m_runs[i].v = std::move(found[i]);
    m_slider_of.clear();
    for (std::size_t k = 0; k < m_sliders.size(); ++k)
      if (!m_sliders[k].stopped)
        m_slider_of.emplace(m_runs[m_sliders[k].run].v[m_sliders[k].index], k);
  }

  /// Stops the vertices at both ends of a chord that is no longer a constrained edge of `cdt`
  /// (a point inserted on it split it) from sliding, so that no chord's bound is measured on a
  /// chord that is not there; returns how many stopped. The optimizers call it first.
  std::size_t stop_at_split_chords(const CDT& cdt) {
    std::size_t stopped = 0;
    const auto stop = [&](Vertex_handle v) {
      const auto it = m_slider_of.find(v);
      if (it == m_slider_of.end()) return;
      m_sliders[it->second].stopped = true;
      m_slider_of.erase(it);
      ++stopped;
    };
    for (const Run& r : m_runs)
      for (std::size_t k = 0; k + 1 < r.v.size(); ++k) {
        typename CDT::Face_handle f;
        int i = 0;
        if (!cdt.is_edge(r.v[k], r.v[k + 1], f, i) || !f->is_constrained(i))
          stop(r.v[k]), stop(r.v[k + 1]);
      }
    return stopped;
  }

  /// \cond SKIP_IN_MANUAL
  // What Cvt_energy_2 calls: before an evaluation; for each cell of a sliding vertex (from
  // several threads, each slider by one); after it, plan() the targets and their move ratios;
  // slide() moves.
  static constexpr std::size_t none = std::size_t(-1);
  std::size_t slider(Vertex_handle v) const {
    const auto it = m_slider_of.find(v);
    return it == m_slider_of.end() ? none : it->second;
  }
  void begin_evaluation() {
    for (Slider& s : m_sliders) s.evaluated = false;
  }
  void set_cell(std::size_t k, const Point_2& centroid, double squared_diameter) {
    Slider& s = m_sliders[k];
    s.centroid = centroid;
    s.diameter2 = squared_diameter;
    s.evaluated = true;
  }
  struct Plan {
    double max_move_ratio = 0, sum_move_ratio = 0;
    std::size_t sliders = 0;  // with a cell
  };
  // Each evaluated slider's constrained centroid and move ratio |x - target| / diameter: the
  // point that slide() would move it to if it were the only one to move.
  Plan plan(const CDT& cdt) {
    Plan p;
    for (Slider& s : m_sliders) {
      if (!s.evaluated) continue;
      const Run& r = m_runs[s.run];
      const std::size_t k = s.index;
      const double lo = r.at[k] - reach * (r.at[k] - r.at[k - 1]);
      const double hi = r.at[k] + reach * (r.at[k + 1] - r.at[k]);
      s.target = reachable(cdt, r, k, nearest(r, lo, hi, s.centroid));
      const double d2 =
          s.target == r.at[k]
              ? 0
              : CGAL::to_double(CGAL::squared_distance(r.v[k]->point(), point_at(r, s.target)));
      const double ratio = s.diameter2 > 0 ? std::sqrt(d2 / s.diameter2) : 0;
      p.max_move_ratio = std::max(p.max_move_ratio, ratio);
      p.sum_move_ratio += ratio;
      ++p.sliders;
    }
    return p;
  }
  // Moves each evaluated slider toward its planned target, as far as the triangulation stays
  // valid and the chords within the bound (halving the way up to eight times), then flips;
  // returns how many moved. `changed`, if not null, gets the faces around each moved vertex and
  // both faces of each flip.
  std::size_t slide(CDT& cdt, std::vector<typename CDT::Face_handle>* changed = nullptr) {
    std::size_t moved = 0;
    m_stack.clear();
    for (Slider& s : m_sliders) {
      if (!s.evaluated) continue;
      s.evaluated = false;  // one slide an evaluation
      Run& r = m_runs[s.run];
      const std::size_t k = s.index;
      double to = reachable(cdt, r, k, s.target);  // its neighbours may have moved
      // Sent back to where its last slide came from, a slider would swing between two places
      // for ever (on a curved run each slide moves the chords its cell is measured against):
      // halfway there instead, so that the swing dies out.
      if (s.has_before && std::abs(to - s.before) <= 1e-9 * std::abs(to - r.at[k]))
        to = reachable(cdt, r, k, (r.at[k] + to) / 2);
      if (to == r.at[k]) continue;
      s.before = r.at[k];
      s.has_before = true;
      r.q[k] = point_at(r, to);
      r.at[k] = to;
      r.v[k]->set_point(r.q[k]);
      ++moved;
      internal::push_star_edges(cdt, r.v[k], m_stack);
      if (changed) internal::push_star(cdt, r.v[k], *changed);
    }
    internal::lawson_flips(cdt, m_stack, [changed](auto f, auto g) {
      if (changed) changed->push_back(f), changed->push_back(g);
    });
    return moved;
  }
  // The arc lengths from the start of `p` to each of its points.
  static std::vector<double> arc_lengths(const std::vector<Point_2>& p) {
    std::vector<double> length(p.size(), 0.0);
    for (std::size_t i = 1; i < p.size(); ++i)
      length[i] =
          length[i - 1] + std::sqrt(CGAL::to_double(CGAL::squared_distance(p[i - 1], p[i])));
    return length;
  }
  /// \endcond

 private:
  static constexpr double reach = 0.45;  // of the way to a neighbour on the run, at most
  static constexpr int halvings = 8;     // of a slide that the bound or the star refuses
  struct Run {
    std::vector<Point_2> p;        // the input polyline
    std::vector<double> length;    // the arc length at each of its points
    std::vector<Vertex_handle> v;  // the vertices on it, in order
    std::vector<double> at;        // their arc lengths
    std::vector<Point_2> q;        // and their points
  };
  struct Slider {
    std::size_t run, index;  // v[index] of m_runs[run]
    Point_2 centroid{};
    double diameter2 = 0;
    bool evaluated = false;
    bool stopped = false;  // by stop_at_split_chords()
    double target = 0;     // the arc length planned
    double before = 0;     // the arc length before its last slide
    bool has_before = false;
  };

  static std::size_t segment_of(const Run& r, double s) {
    const std::size_t m = r.p.size() - 1;
    const auto it = std::upper_bound(r.length.begin(), r.length.end(), s);
    const std::size_t i = it == r.length.begin() ? 0 : std::size_t(it - r.length.begin()) - 1;
    return std::min(i, m - 1);
  }
  // The point at arc length s, on its input segment in double precision.
  static Point_2 point_at(const Run& r, double s) {
    const std::size_t i = segment_of(r, s);
    const double len = r.length[i + 1] - r.length[i];
    const double t = len > 0 ? std::clamp((s - r.length[i]) / len, 0.0, 1.0) : 0.0;
    if (t == 0) return r.p[i];
    if (t == 1) return r.p[i + 1];
    const double ax = CGAL::to_double(r.p[i].x()), ay = CGAL::to_double(r.p[i].y());
    return Point_2(ax + t * (CGAL::to_double(r.p[i + 1].x()) - ax),
                   ay + t * (CGAL::to_double(r.p[i + 1].y()) - ay));
  }
  // The arc length in [lo, hi] of the point of the run nearest to c (the first of equals).
  static double nearest(const Run& r, double lo, double hi, const Point_2& c) {
    const double cx = CGAL::to_double(c.x()), cy = CGAL::to_double(c.y());
    double best = lo, best_d2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = segment_of(r, lo); i <= segment_of(r, hi); ++i) {
      const double s0 = std::max(lo, r.length[i]), s1 = std::min(hi, r.length[i + 1]);
      if (s1 < s0) continue;
      const double ax = CGAL::to_double(r.p[i].x()), ay = CGAL::to_double(r.p[i].y());
      const double dx = CGAL::to_double(r.p[i + 1].x()) - ax,
                   dy = CGAL::to_double(r.p[i + 1].y()) - ay;
      const double len = r.length[i + 1] - r.length[i];
      const double u = len > 0 ? ((cx - ax) * dx + (cy - ay) * dy) / (len * len) : 0;
      const double s = std::clamp(r.length[i] + u * len, s0, s1);
      const double t = len > 0 ? (s - r.length[i]) / len : 0;
      const double ex = ax + t * dx - cx, ey = ay + t * dy - cy;
      if (ex * ex + ey * ey < best_d2) best_d2 = ex * ex + ey * ey, best = s;
    }
    return best;
  }
  // The arc length `to`, or the first of the points half as far from vertex k of r, then half
  // as far again (up to `halvings` times), where its chords stay within the bound and the
  // triangulation valid; else, or where a point is where the vertex is, the vertex's own.
  double reachable(const CDT& cdt, const Run& r, std::size_t k, double to) const {
    const double from = r.at[k];
    for (int attempt = 0; attempt < halvings && to != from;
         ++attempt, to = from + (to - from) / 2) {
      const Point_2 q = point_at(r, to);
      if (q == r.v[k]->point()) break;
      if (within_bound(r, k, to, q) && internal::stays_valid_at(cdt, r.v[k], q)) return to;
    }
    return from;
  }
  // Whether the chords of vertex k of r at arc length `to`, at q, stay within the bound.
  bool within_bound(const Run& r, std::size_t k, double to, const Point_2& q) const {
    const double b2 = m_bound * m_bound;
    return chord_deviation2(r, r.at[k - 1], r.v[k - 1]->point(), to, q) <= b2 &&
           chord_deviation2(r, to, q, r.at[k + 1], r.v[k + 1]->point()) <= b2;
  }
  // The largest squared distance from the input vertices strictly between arc lengths s and t
  // to the chord from a to b.
  static double chord_deviation2(const Run& r, double s, const Point_2& a, double t,
                                 const Point_2& b) {
    double worst = 0;
    const typename CDT::Geom_traits::Segment_2 chord(a, b);
    for (std::size_t i = segment_of(r, s) + 1; i < r.p.size() && r.length[i] < t; ++i)
      if (r.length[i] > s)
        worst = std::max(worst, CGAL::to_double(CGAL::squared_distance(r.p[i], chord)));
    return worst;
  }
  std::vector<Run> m_runs;
  std::vector<Slider> m_sliders;
  std::unordered_map<Vertex_handle, std::size_t> m_slider_of;
  double m_bound = std::numeric_limits<double>::infinity();
  std::vector<internal::Flip_candidate<CDT>> m_stack;
};

/// \ingroup PkgCvt2Ref
/// Where the vertices on constraints of a triangulation were, taken before an optimization with
/// `sliding_runs()`: after it, `follow()` moves each point where such a vertex was to where the
/// vertex is now. Lines known by their ends (the input's segments, which name the chords:
/// `IO::constrained_edge_items()`) then meet the slid triangulation's vertices.
template <class CDT>
class Slid_vertices_2 {
 public:
  using Point_2 = typename CDT::Point_2;  ///< point type

  /// every vertex of `cdt` on a constraint, and where it is
  explicit Slid_vertices_2(const CDT& cdt) {
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      if (cdt.are_there_incident_constraints(v)) m_was.emplace_back(v, v->point());
  }
  /// Replaces each point of `points` where a vertex was by where it is (the vertices must still
  /// be in the triangulation); the others stay.
  void follow(std::vector<Point_2>& points) const {
    std::map<Point_2, Point_2> now;
    for (const auto& [v, p] : m_was) now.emplace(p, v->point());
    for (Point_2& p : points)
      if (const auto it = now.find(p); it != now.end()) p = it->second;
  }

 private:
  std::vector<std::pair<typename CDT::Vertex_handle, Point_2>> m_was;
};

}  // namespace CVT_2

#endif  // CVT_2_SLIDING_RUNS_2_H
