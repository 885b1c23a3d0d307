// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Run_resampler: the constraint graph of a marked triangulation cut into runs between features,
// each run replaced by points on it about spacing_ratio cell sizes apart, and more input vertices
// kept where a chord would leave the input too far or change the topology;
// resample_constraints_2()'s work.
#ifndef CVT_2_INTERNAL_RESAMPLE_RUNS_H
#define CVT_2_INTERNAL_RESAMPLE_RUNS_H

#include <CGAL/Bbox_2.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/enum.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

template <class CDT>
class Run_resampler {
 public:
  using Point_2 = typename CDT::Point_2;
  using Vertex_handle = typename CDT::Vertex_handle;
  using Face_handle = typename CDT::Face_handle;

  // A chord of the result between points()[a] and points()[b], with the domain's marks on its
  // left and right going from a to b.
  struct Chord {
    std::size_t a, b;
    bool left_inside, right_inside;
    Point_2 source_a, source_b;  // the input segment of its stretch nearest to its middle
  };

  // A run of the result with the domain on a side: its input polyline, and its points in order
  // (numbers in points()), each on segment seg[k] of it at parameter t[k].
  struct Resampled_run {
    std::vector<Point_2> polyline;
    std::vector<std::size_t> points, seg;
    std::vector<double> t;
  };

  // What resample() counted.
  std::size_t input_vertices = 0, output_vertices = 0, features = 0, corners = 0, runs = 0;
  std::size_t kept_for_deviation = 0, kept_for_topology = 0;
  std::size_t rings_dropped = 0, generators_dropped = 0;
  double max_deviation = 0;

  Run_resampler(const CDT& cdt, double h, double spacing, double bound, double corner_angle,
                const std::vector<Point_2>& fixed, double minimum_ring_area)
      : m_cdt(cdt),
        m_h(h),
        m_spacing(spacing),
        m_bound(bound),
        m_corner(corner_angle),
        m_minimum_ring_area(minimum_ring_area) {
    collect(std::set<Point_2>(fixed.begin(), fixed.end()));
    drop_inside_dropped_rings();
  }

  void resample() {
    for (Run& r : m_runs) place_nodes(r);
    for (;;) {
      keep_within_bound();
      if (!keep_topology()) break;
    }
    finish();
  }

  // The vertices of the result: the generators of the input, then the runs' points.
  const std::vector<Point_2>& points() const { return m_points; }
  const std::vector<Chord>& chords() const { return m_chords; }
  const std::vector<Resampled_run>& resampled_runs() const { return m_resampled; }

  // The domain's area and its boundary's length (the constrained edges with the domain on one
  // side): sums of sorted terms, the same bits whatever the triangulation's layout.
  static double domain_area(const CDT& cdt) {
    std::vector<double> terms;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if (f->is_inside_domain()) terms.push_back(CGAL::to_double(cdt.triangle(f).area()));
    return sorted_sum(terms);
  }
  static double boundary_length(const CDT& cdt) {
    std::vector<double> terms;
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
      if (cdt.is_constrained(*e) &&
          inside(cdt, e->first) != inside(cdt, e->first->neighbor(e->second)))
        terms.push_back(std::sqrt(CGAL::to_double(cdt.segment(*e).squared_length())));
    return sorted_sum(terms);
  }
  static double sorted_sum(std::vector<double>& terms) {
    std::sort(terms.begin(), terms.end());
    double sum = 0;
    for (const double t : terms) sum += t;
    return sum;
  }

  static bool inside(const CDT& cdt, Face_handle f) {
    return !cdt.is_infinite(f) && f->is_inside_domain();
  }

 private:
  // A point of a run, at p[seg] + t (p[seg + 1] - p[seg]), 0 <= t < 1; t = 0 is the vertex.
  struct Node {
    std::size_t seg;
    double t;
    Point_2 q;
    double pos() const { return double(seg) + t; }
  };
  // A polyline between two features (p.front() and p.back(), equal on a ring without one).
  struct Run {
    std::vector<Point_2> p;
    bool left_inside, right_inside;
    std::vector<Node> nodes;
    bool keep() const { return !left_inside && !right_inside; }
  };

  // --- the runs ---------------------------------------------------------------------------------

  // The constraint graph, its vertices numbered in the order of their points and each one's
  // neighbours in that order, so that the runs do not depend on the triangulation's layout.
  void collect(const std::set<Point_2>& fixed) {
    std::map<Point_2, Vertex_handle> by_point;
    std::vector<std::pair<Vertex_handle, Vertex_handle>> edges;
    for (auto e = m_cdt.finite_edges_begin(); e != m_cdt.finite_edges_end(); ++e) {
      if (!m_cdt.is_constrained(*e)) continue;
      edges.emplace_back(e->first->vertex(CDT::ccw(e->second)),
                         e->first->vertex(CDT::cw(e->second)));
      by_point.emplace(edges.back().first->point(), edges.back().first);
      by_point.emplace(edges.back().second->point(), edges.back().second);
    }
    std::unordered_map<const void*, std::size_t> index;
    std::vector<Vertex_handle> vertex;
    for (const auto& [p, v] : by_point) index.emplace(&*v, vertex.size()), vertex.push_back(v);
    std::vector<std::vector<std::size_t>> adjacent(vertex.size());
    for (const auto& [a, b] : edges) {
      const std::size_t u = index.at(&*a), v = index.at(&*b);
      adjacent[u].push_back(v), adjacent[v].push_back(u);
    }
    for (auto& n : adjacent) std::sort(n.begin(), n.end());
    for (auto v = m_cdt.finite_vertices_begin(); v != m_cdt.finite_vertices_end(); ++v)
      if (index.count(&*v) == 0) m_points.push_back(v->point());  // a generator
    std::sort(m_points.begin(), m_points.end());
    input_vertices = vertex.size();
    std::vector<bool> feature(vertex.size()), visited(vertex.size(), false);
    for (std::size_t v = 0; v < vertex.size(); ++v)
      feature[v] = adjacent[v].size() != 2 || fixed.count(vertex[v]->point()) > 0;
    features = std::size_t(std::count(feature.begin(), feature.end(), true));

    const auto trace = [&](std::size_t from, std::size_t next) {
      std::vector<std::size_t> chain{from};
      std::size_t prev = from, cur = next;
      while (cur != from && !feature[cur]) {
        visited[cur] = true;
        chain.push_back(cur);
        const std::size_t n = adjacent[cur][0] == prev ? adjacent[cur][1] : adjacent[cur][0];
        prev = cur, cur = n;
      }
      chain.push_back(cur);
      std::vector<Point_2> p;
      for (const std::size_t v : chain) p.push_back(vertex[v]->point());
      return std::make_pair(std::move(p), chain);
    };
    std::set<std::pair<std::size_t, std::size_t>> done;  // the first and last edge of each chain
    const auto edge = [](std::size_t a, std::size_t b) {
      return std::pair<std::size_t, std::size_t>(std::min(a, b), std::max(a, b));
    };
    for (std::size_t s = 0; s < vertex.size(); ++s) {
      if (!feature[s]) continue;
      for (const std::size_t n : adjacent[s]) {
        if (done.count(edge(s, n))) continue;
        auto [p, chain] = trace(s, n);
        done.insert(edge(s, n));
        done.insert(edge(chain[chain.size() - 2], chain.back()));
        add_chain(std::move(p), sides(vertex[chain[0]], vertex[chain[1]]), false);
      }
    }
    for (std::size_t s = 0; s < vertex.size(); ++s)
      if (!feature[s] && !visited[s]) {  // a ring without features
        visited[s] = true;
        auto [p, chain] = trace(s, adjacent[s][0]);
        if (std::abs(area(p)) < m_minimum_ring_area) {
          m_dropped.push_back(std::move(p));
          continue;
        }
        add_chain(std::move(p), sides(vertex[chain[0]], vertex[chain[1]]), true);
      }
    runs = m_runs.size();
  }

  // The signed area of the closed polyline p (p.front() == p.back()), by the shoelace formula
  // about its first point.
  static double area(const std::vector<Point_2>& p) {
    double a = 0;
    for (std::size_t i = 1; i + 1 < p.size(); ++i)
      a += CGAL::to_double(CGAL::area(p[0], p[i], p[i + 1]));
    return a;
  }

  // The winding number of the closed polyline through [first, last) (closed from the last point
  // to the first) around x, by exact orientations; x on it counts as 0.
  template <class Iterator>
  static int winding(Iterator first, Iterator last, const Point_2& x) {
    int w = 0;
    for (Iterator i = first; i != last; ++i) {
      const Iterator j = std::next(i) == last ? first : std::next(i);
      const Point_2 &u = *i, &v = *j;
      if (u.y() <= x.y()) {
        if (v.y() > x.y() && CGAL::orientation(u, v, x) == CGAL::LEFT_TURN) ++w;
      } else if (v.y() <= x.y() && CGAL::orientation(u, v, x) == CGAL::RIGHT_TURN) {
        --w;
      }
    }
    return w;
  }

  // The rings smaller than the minimum area go with everything inside them: the runs (which
  // cannot cross them, so one vertex says) and the generators.
  void drop_inside_dropped_rings() {
    rings_dropped = m_dropped.size();
    if (m_dropped.empty()) return;
    std::vector<CGAL::Bbox_2> boxes;
    for (const auto& ring : m_dropped) {
      CGAL::Bbox_2 b;
      for (const Point_2& q : ring) b += q.bbox();
      boxes.push_back(b);
    }
    const auto in_dropped = [&](const Point_2& x) {
      for (std::size_t i = 0; i < m_dropped.size(); ++i)
        if (CGAL::do_overlap(boxes[i], x.bbox()) &&
            winding(m_dropped[i].begin(), m_dropped[i].end() - 1, x) != 0)
          return true;
      return false;
    };
    m_runs.erase(std::remove_if(m_runs.begin(), m_runs.end(),
                                [&](const Run& r) {
                                  const bool in = in_dropped(r.p[1]);
                                  rings_dropped += in && r.p.front() == r.p.back();
                                  return in;
                                }),
                 m_runs.end());
    const std::size_t generators = m_points.size();
    m_points.erase(std::remove_if(m_points.begin(), m_points.end(), in_dropped), m_points.end());
    generators_dropped = generators - m_points.size();
    runs = m_runs.size();
  }

  // The domain's marks on the left and right of the constrained edge from u to v.
  std::pair<bool, bool> sides(Vertex_handle u, Vertex_handle v) const {
    Face_handle f;
    int i = 0;
    m_cdt.is_edge(u, v, f, i);
    const Face_handle g = f->neighbor(i);
    const bool f_left = f->vertex(CDT::ccw(i)) == u;
    return f_left ? std::make_pair(inside(m_cdt, f), inside(m_cdt, g))
                  : std::make_pair(inside(m_cdt, g), inside(m_cdt, f));
  }

  // Cuts the chain p at its corners into runs; a ring (p.front() == p.back(), no feature) with
  // none stays one run, from its vertex of largest turn.
  void add_chain(std::vector<Point_2> p, std::pair<bool, bool> marks, bool ring) {
    std::vector<std::size_t> cut;  // the corners, in order along p
    if (!(marks.first || marks.second)) {
      // kept as it is: no corners needed
    } else {
      const std::size_t m = p.size() - 1;
      std::vector<std::pair<double, std::size_t>> turns;
      for (std::size_t v = ring ? 0 : 1; v < m; ++v) turns.emplace_back(turn(p, ring, v), v);
      std::vector<std::pair<double, std::size_t>> candidates;
      for (const auto& tv : turns)
        if (tv.first > m_corner) candidates.push_back(tv);
      std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
        return a.first > b.first || (a.first == b.first && a.second < b.second);
      });
      // A turn is measured between the points h away, so the vertices within h of a corner (or
      // of a feature at the chain's end) see its turn too: of corners closer than h, the
      // sharpest stays.
      const auto near = [&](const Point_2& a, const Point_2& b) {
        return CGAL::to_double(CGAL::squared_distance(a, b)) < m_h * m_h;
      };
      for (const auto& [t, v] : candidates) {
        if (!ring && (near(p[v], p.front()) || near(p[v], p.back()))) continue;
        bool ok = true;
        for (const std::size_t c : cut) ok = ok && !near(p[v], p[c]);
        if (ok) cut.push_back(v);
      }
      std::sort(cut.begin(), cut.end());
      corners += cut.size();
      features += cut.size();
      if (ring && cut.empty() && !turns.empty()) {
        const auto best =
            std::max_element(turns.begin(), turns.end(), [](const auto& a, const auto& b) {
              return a.first < b.first || (a.first == b.first && a.second > b.second);
            });
        std::rotate(p.begin(), p.begin() + std::ptrdiff_t(best->second), p.end() - 1);
        p.back() = p.front();
        m_runs.push_back({std::move(p), marks.first, marks.second, {}});
        return;
      }
      if (ring && !cut.empty()) {  // start at the first corner
        const std::size_t s = cut.front();
        std::rotate(p.begin(), p.begin() + std::ptrdiff_t(s), p.end() - 1);
        p.back() = p.front();
        for (std::size_t& c : cut) c -= s;
        cut.erase(cut.begin());
      }
    }
    std::size_t from = 0;
    cut.push_back(p.size() - 1);
    for (const std::size_t to : cut) {
      m_runs.push_back({std::vector<Point_2>(p.begin() + std::ptrdiff_t(from),
                                             p.begin() + std::ptrdiff_t(to) + 1),
                        marks.first,
                        marks.second,
                        {}});
      from = to;
    }
  }

  // The point where the polyline, going from c (on it) through b, first reaches the distance r
  // from c, with a inside that distance and b not: on the segment ab, at the parameter returned.
  static double crossing(const Point_2& c, const Point_2& a, const Point_2& b, double r) {
    const double dx = CGAL::to_double(b.x() - a.x()), dy = CGAL::to_double(b.y() - a.y());
    const double ex = CGAL::to_double(a.x() - c.x()), ey = CGAL::to_double(a.y() - c.y());
    const double dd = dx * dx + dy * dy, ed = ex * dx + ey * dy, ee = ex * ex + ey * ey;
    const double disc = std::max(0.0, ed * ed - dd * (ee - r * r));
    return std::clamp((-ed + std::sqrt(disc)) / dd, 0.0, 1.0);
  }
  static Point_2 at(const Point_2& a, const Point_2& b, double t) {
    return Point_2(CGAL::to_double(a.x()) + t * (CGAL::to_double(b.x()) - CGAL::to_double(a.x())),
                   CGAL::to_double(a.y()) + t * (CGAL::to_double(b.y()) - CGAL::to_double(a.y())));
  }
  static double distance2(const Point_2& a, const Point_2& b) {
    return CGAL::to_double(CGAL::squared_distance(a, b));
  }

  // The turn of the polyline at p[v], in radians: the angle between the chords from the point a
  // cell size before to p[v] and from p[v] to the point a cell size after (or the ends).
  double turn(const std::vector<Point_2>& p, bool ring, std::size_t v) const {
    const std::size_t m = p.size() - 1;  // on a ring p[m] == p[0]
    const auto step = [&](std::size_t i, int dir) -> std::size_t {
      if (dir > 0) return ring ? (i + 1) % m : i + 1;
      return ring ? (i + m - 1) % m : i - 1;
    };
    const auto reach = [&](int dir) {
      std::size_t i = v;
      for (std::size_t k = 0; k < m; ++k) {
        if (!ring && (dir > 0 ? i == m : i == 0)) return p[i];
        const std::size_t j = step(i, dir);
        if (distance2(p[j], p[v]) >= m_h * m_h)
          return at(p[i], p[j], crossing(p[v], p[i], p[j], m_h));
        i = j;
      }
      return p[step(v, dir)];  // a ring smaller than the size
    };
    const Point_2 before = reach(-1), after = reach(+1);
    const double ax = CGAL::to_double(p[v].x() - before.x()),
                 ay = CGAL::to_double(p[v].y() - before.y());
    const double bx = CGAL::to_double(after.x() - p[v].x()),
                 by = CGAL::to_double(after.y() - p[v].y());
    return std::abs(std::atan2(ax * by - ay * bx, ax * bx + ay * by));
  }

  // --- resampling -------------------------------------------------------------------------------

  // The divider walk with step s from p.front(): each point the first one along the polyline at
  // distance s from the last. Returns the number of steps, the rest to p.back() as a fraction.
  double divide(const Run& r, double s, std::vector<Node>* out) const {
    const std::vector<Point_2>& p = r.p;
    const std::size_t m = p.size() - 1;
    Point_2 c = p[0];
    std::size_t seg = 0;
    double t = 0, steps = 0;
    for (;;) {
      std::size_t j = seg;
      Point_2 a = c;
      double t0 = t;  // a's parameter on segment j
      while (j < m && distance2(p[j + 1], c) < s * s) a = p[j + 1], t0 = 0, ++j;
      if (j == m) return steps + std::sqrt(distance2(p[m], c)) / s;
      const double u = crossing(c, a, p[j + 1], s);
      t = t0 + u * (1 - t0);
      seg = j;
      c = at(p[j], p[j + 1], t);
      steps += 1;
      if (out) out->push_back({seg, t, c});
      if (steps > 4 * double(m) + 1e6) return steps;  // a guard; cannot happen for s > 0
    }
  }

  void place_nodes(Run& r) {
    const std::size_t m = r.p.size() - 1;
    const bool closed = r.p.front() == r.p.back();
    const auto all_vertices = [&] {
      r.nodes.clear();
      for (std::size_t i = 0; i <= m; ++i) r.nodes.push_back({i, 0, r.p[i]});
    };
    if (r.keep()) return all_vertices();
    const double raw = divide(r, m_spacing, nullptr);
    std::size_t k = std::max<std::size_t>(closed ? 3 : 1, std::size_t(std::llround(raw)));
    // No more points than the input has: generators on a long straight edge cost more energy
    // than the free ones its clipped cells have (measured: the square at 2 000 cells, 1.057
    // against 1.017).
    if (k >= m) return all_vertices();
    r.nodes = {{0, 0, r.p[0]}};
    if (k > 1) {
      double lo = m_spacing / 2, hi = m_spacing * 2;
      while (divide(r, lo, nullptr) < double(k) && lo > m_spacing * 1e-6) lo /= 2;
      while (divide(r, hi, nullptr) > double(k) && hi < m_spacing * 1e6) hi *= 2;
      if (divide(r, lo, nullptr) < double(k)) return all_vertices();
      for (int i = 0; i < 50; ++i) {
        const double mid = (lo + hi) / 2;
        (divide(r, mid, nullptr) >= double(k) ? lo : hi) = mid;
      }
      std::vector<Node> inner;
      divide(r, lo, &inner);
      while (!inner.empty() &&
             (inner.size() >= k || distance2(inner.back().q, r.p[m]) < lo * lo / 4))
        inner.pop_back();
      for (Node& n : inner) {
        if (n.t <= 1e-12) n.t = 0, n.q = r.p[n.seg];
        if (n.t >= 1 - 1e-12) ++n.seg, n.t = 0, n.q = r.p[n.seg];
        if (n.seg < m && n.pos() > r.nodes.back().pos()) r.nodes.push_back(n);
      }
      if (closed && r.nodes.size() < 3) return all_vertices();  // a ring keeps three points
    }
    r.nodes.push_back({m, 0, r.p[m]});
  }

  // The input vertices strictly between nodes j and j + 1 of r: [first, last).
  static std::pair<std::size_t, std::size_t> interior(const Run& r, std::size_t j) {
    const Node &a = r.nodes[j], &b = r.nodes[j + 1];
    return {a.seg + 1, b.t > 0 ? b.seg + 1 : b.seg};
  }

  // Keeps in r the input vertex strictly between nodes j and j + 1 farthest from their chord;
  // returns its squared distance (0 and nothing kept if there is none).
  double farthest(const Run& r, std::size_t j, std::size_t* v) const {
    const auto [first, last] = interior(r, j);
    const typename CDT::Geom_traits::Segment_2 chord(r.nodes[j].q, r.nodes[j + 1].q);
    double worst = -1;
    for (std::size_t i = first; i < last; ++i) {
      const double d = CGAL::to_double(CGAL::squared_distance(r.p[i], chord));
      if (d > worst) worst = d, *v = i;
    }
    return worst;
  }

  void keep_vertex(Run& r, std::size_t j, std::size_t v) {
    r.nodes.insert(r.nodes.begin() + std::ptrdiff_t(j) + 1, Node{v, 0, r.p[v]});
  }

  void keep_within_bound() {
    for (Run& r : m_runs)
      for (std::size_t j = 0; j + 1 < r.nodes.size();) {
        std::size_t v = 0;
        if (farthest(r, j, &v) > m_bound * m_bound)
          keep_vertex(r, j, v), ++kept_for_deviation;
        else
          ++j;
      }
  }

  // --- topology ---------------------------------------------------------------------------------

  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

  // Whether the segments ab and cd meet anywhere but at one shared end.
  static bool conflict(const Point_2& a, const Point_2& b, const Point_2& c, const Point_2& d) {
    const int shared = (a == c) + (a == d) + (b == c) + (b == d);
    if (shared >= 2) return true;
    if (shared == 1) {
      const Point_2& p = (a == c || a == d) ? a : b;
      const Point_2& x = p == a ? b : a;
      const Point_2& y = p == c ? d : c;
      return CGAL::orientation(p, x, y) == CGAL::COLLINEAR && CGAL::angle(x, p, y) == CGAL::ACUTE;
    }
    return CGAL::do_intersect(typename CDT::Geom_traits::Segment_2(a, b),
                              typename CDT::Geom_traits::Segment_2(c, d));
  }

  // Whether x lies on the chord of nodes j, j + 1 of r or in the region between it and the input
  // polyline (nonzero winding number, exact orientations).
  static bool swept(const Run& r, std::size_t j, const Point_2& x) {
    const Point_2 &a = r.nodes[j].q, &b = r.nodes[j + 1].q;
    // An end that is an input vertex may be x itself (a feature other runs share); a computed
    // end that lands on x would merge x into the run.
    if (x == a) return r.nodes[j].t > 0;
    if (x == b) return r.nodes[j + 1].t > 0;
    if (CGAL::orientation(a, b, x) == CGAL::COLLINEAR &&
        CGAL::collinear_are_strictly_ordered_along_line(a, x, b))
      return true;
    const auto [first, last] = interior(r, j);
    std::vector<Point_2> region{a};
    region.insert(region.end(), r.p.begin() + std::ptrdiff_t(first),
                  r.p.begin() + std::ptrdiff_t(last));
    region.push_back(b);
    return winding(region.begin(), region.end(), x) != 0;
  }

  // Finds the chords that cross an input segment or another chord, or sweep over a vertex or a
  // generator, and keeps an input vertex in each (or the input segment it lies on, if it has
  // none). Returns whether that changed a run: a chord that is its input segment already and
  // still conflicts (input lines that touch) stays as the input has it, and the passes end.
  bool keep_topology() {
    struct Ref {
      std::size_t run, j;
    };
    std::vector<Ref> chords;
    std::vector<Box> regions, segments, items;
    for (std::size_t ri = 0; ri < m_runs.size(); ++ri) {
      const Run& r = m_runs[ri];
      for (std::size_t j = 0; j + 1 < r.nodes.size(); ++j) {
        CGAL::Bbox_2 region = r.nodes[j].q.bbox() + r.nodes[j + 1].q.bbox();
        const auto [first, last] = interior(r, j);
        for (std::size_t i = first; i < last; ++i) region += r.p[i].bbox();
        regions.emplace_back(region, chords.size());
        segments.emplace_back(r.nodes[j].q.bbox() + r.nodes[j + 1].q.bbox(), chords.size());
        chords.push_back({ri, j});
      }
    }
    // The items: input segments (run, segment) and vertices (run, vertex), then generators.
    std::vector<std::pair<std::size_t, std::size_t>> item_ref;
    std::vector<bool> is_segment;
    for (std::size_t ri = 0; ri < m_runs.size(); ++ri) {
      const Run& r = m_runs[ri];
      for (std::size_t s = 0; s + 1 < r.p.size(); ++s) {
        items.emplace_back(r.p[s].bbox() + r.p[s + 1].bbox(), item_ref.size());
        item_ref.emplace_back(ri, s), is_segment.push_back(true);
      }
      for (std::size_t s = 0; s < r.p.size(); ++s) {  // with the features, repeated
        items.emplace_back(r.p[s].bbox(), item_ref.size());
        item_ref.emplace_back(ri, s), is_segment.push_back(false);
      }
    }
    for (std::size_t g = 0; g < m_points.size(); ++g) {
      items.emplace_back(m_points[g].bbox(), item_ref.size());
      item_ref.emplace_back(m_runs.size(), g), is_segment.push_back(false);
    }
    std::set<std::pair<std::size_t, std::size_t>> bad;  // (run, j)
    const auto chord = [&](const Ref& c, std::size_t e) { return m_runs[c.run].nodes[c.j + e].q; };
    CGAL::box_intersection_d(
        regions.begin(), regions.end(), items.begin(), items.end(),
        [&](const Box& rb, const Box& ib) {
          const Ref& c = chords[rb.info()];
          const Run& r = m_runs[c.run];
          const auto [ri, k] = item_ref[ib.info()];
          if (is_segment[ib.info()]) {
            if (ri == c.run && k >= r.nodes[c.j].seg && double(k) < r.nodes[c.j + 1].pos())
              return;  // a piece of the chord's own polyline
            const Run& o = m_runs[ri];
            if (conflict(chord(c, 0), chord(c, 1), o.p[k], o.p[k + 1])) bad.emplace(c.run, c.j);
            return;
          }
          if (ri == c.run) {
            const auto [first, last] = interior(r, c.j);
            if (k >= first && k < last) return;  // a vertex the chord replaces
          }
          const Point_2& x = ri < m_runs.size() ? m_runs[ri].p[k] : m_points[k];
          if (swept(r, c.j, x)) bad.emplace(c.run, c.j);
        });
    CGAL::box_self_intersection_d(
        segments.begin(), segments.end(), [&](const Box& a, const Box& b) {
          const Ref &c = chords[a.info()], &d = chords[b.info()];
          if (conflict(chord(c, 0), chord(c, 1), chord(d, 0), chord(d, 1)))
            bad.emplace(c.run, c.j), bad.emplace(d.run, d.j);
        });
    // From the last chord of each run to the first, so that the earlier indices stay valid; a
    // run whose nodes a fallback rebuilt waits for the next pass, which finds its chords again.
    std::size_t rebuilt = m_runs.size();
    bool changed = false;
    for (auto it = bad.rbegin(); it != bad.rend(); ++it) {
      if (it->first == rebuilt) continue;
      Run& r = m_runs[it->first];
      const std::size_t j = it->second;
      std::size_t v = 0;
      if (farthest(r, j, &v) >= 0) {
        keep_vertex(r, j, v), ++kept_for_topology, changed = true;
        continue;
      }
      // No input vertex between: the chord lies on one input segment; take that segment.
      const std::size_t s = r.nodes[j].seg;
      std::vector<Node> nodes;
      for (const Node& n : r.nodes)
        if (n.seg != s || n.t == 0) nodes.push_back(n);
      for (const std::size_t v : {s, s + 1}) {
        const auto at_or_after = std::find_if(nodes.begin(), nodes.end(),
                                              [&](const Node& n) { return n.pos() >= double(v); });
        if (at_or_after == nodes.end() || at_or_after->pos() != double(v))
          nodes.insert(at_or_after, Node{v, 0, r.p[v]});
      }
      const auto same_node = [](const Node& x, const Node& y) { return x.pos() == y.pos(); };
      if (std::equal(nodes.begin(), nodes.end(), r.nodes.begin(), r.nodes.end(), same_node))
        continue;  // the chord is the input segment: nothing to keep
      r.nodes = std::move(nodes);
      rebuilt = it->first;
      ++kept_for_topology, changed = true;
    }
    return changed;
  }

  // --- the result -------------------------------------------------------------------------------

  void finish() {
    std::map<Point_2, std::size_t> index;
    const std::size_t generators = m_points.size();
    const auto id = [&](const Point_2& p) {
      const auto [it, is_new] = index.emplace(p, m_points.size());
      if (is_new) m_points.push_back(p);
      return it->second;
    };
    for (const Run& r : m_runs) {
      for (std::size_t j = 0; j + 1 < r.nodes.size(); ++j) {
        std::size_t v = 0;
        const double d = farthest(r, j, &v);
        if (d > 0) max_deviation = std::max(max_deviation, std::sqrt(d));
        // its source: the input segment of its stretch of the run nearest to its middle, within
        // the deviation bound of it (the stretch is within the bound of the chord, end to end)
        const Point_2 middle = CGAL::midpoint(r.nodes[j].q, r.nodes[j + 1].q);
        const std::size_t last = std::min(r.nodes[j + 1].seg, r.p.size() - 2);
        std::size_t s = std::min(r.nodes[j].seg, last);
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = s; k <= last; ++k) {
          const double to_k = CGAL::to_double(CGAL::squared_distance(
              middle, typename CDT::Geom_traits::Segment_2(r.p[k], r.p[k + 1])));
          if (to_k < nearest) nearest = to_k, s = k;
        }
        m_chords.push_back({id(r.nodes[j].q), id(r.nodes[j + 1].q), r.left_inside, r.right_inside,
                            r.p[s], r.p[s + 1]});
      }
      if (r.keep() || r.nodes.size() < 3) continue;
      Resampled_run out{r.p, {}, {}, {}};
      for (const Node& n : r.nodes) {
        out.points.push_back(id(n.q));
        out.seg.push_back(n.seg);
        out.t.push_back(n.t);
      }
      m_resampled.push_back(std::move(out));
    }
    output_vertices = m_points.size() - generators;
  }

  const CDT& m_cdt;
  // the cell size (corners are measured at its scale), the nodes' spacing along a run
  double m_h, m_spacing, m_bound, m_corner, m_minimum_ring_area;
  std::vector<Run> m_runs;
  std::vector<std::vector<Point_2>> m_dropped;  // the rings below the minimum area
  std::vector<Point_2> m_points;
  std::vector<Chord> m_chords;
  std::vector<Resampled_run> m_resampled;
};

// Marks the faces of `cdt` by the sides of its constraints: a face reached from the unbounded
// face without crossing a constraint is outside; any other region takes the mark that
// `left_inside` gives the first constrained edge met, seen from its side.
template <class CDT, class Map>
void mark_by_sides(CDT& cdt, const Map& left_inside) {
  using Face_handle = typename CDT::Face_handle;
  std::unordered_set<Face_handle> seen;
  std::vector<Face_handle> region, stack;
  for (auto start = cdt.all_faces_begin(); start != cdt.all_faces_end(); ++start) {
    if (!seen.insert(Face_handle(start)).second) continue;
    region.clear(), stack.assign(1, start);
    bool infinite = false, known = false, in = false;
    while (!stack.empty()) {
      const Face_handle f = stack.back();
      stack.pop_back();
      region.push_back(f);
      infinite = infinite || cdt.is_infinite(f);
      for (int i = 0; i < 3; ++i) {
        if (cdt.is_constrained({f, i})) {
          if (!known) {
            const auto it = left_inside.find({&*f->vertex(CDT::ccw(i)), &*f->vertex(CDT::cw(i))});
            if (it != left_inside.end()) known = true, in = it->second;
          }
        } else if (seen.insert(f->neighbor(i)).second) {
          stack.push_back(f->neighbor(i));
        }
      }
    }
    for (const Face_handle f : region) f->set_inside_domain(!infinite && known && in);
  }
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_RESAMPLE_RUNS_H
