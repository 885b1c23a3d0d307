// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Conforming lines as one network: nodes shared at corners and junctions, each node's circle,
// the pair mirrored across each step, steps refined where a pair falls in another circle.
#ifndef CVT_2_INTERNAL_CONFORMING_NETWORK_H
#define CVT_2_INTERNAL_CONFORMING_NETWORK_H

#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/internal/crossing_segments.h>
#include <CVT_2/internal/input_segments_of_constraints.h>
#include <CVT_2/internal/to_string.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <queue>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// How far inside a circle of centre (x, y) and radius r a point must be to count as inside: the
// pairs lie on the circles, computed in doubles, so a rounding of the radius and of the
// coordinates' magnitude (at (5e5, 5e6) a unit in the last place is 1e-9, the radius of a
// cell of half a metre 3e-10 of it).
inline double circle_rounding(double x, double y, double r) {
  return 1e-9 * r + std::ldexp(std::max(std::abs(x), std::abs(y)), -48);
}

// Circles found by the points they hold by more than circle_rounding(): in grids by size, each
// circle in that of cells as wide as the smallest power of two of the largest radius at least
// its own, so that a point meets few circles in each, however many tiny ones crowd a place.
class Circle_grid {
 public:
  struct Circle {
    double x, y, r;
  };
  // Holds `circles` (any before gone: the largest radius sets the cells).
  void assign(std::vector<Circle> circles) {
    m_circles = std::move(circles);
    m_largest = 0;
    for (const Circle& c : m_circles) m_largest = std::max(m_largest, c.r);
    m_grids.clear();
    for (std::size_t i = 0; i < m_circles.size(); ++i) {
      const Circle& c = m_circles[i];
      const int size = std::clamp(int(std::ceil(std::log2(c.r / m_largest))), -60, 0);
      m_grids[size].emplace(key(cell(c.x, size), cell(c.y, size)), i);
    }
  }
  const std::vector<Circle>& circles() const { return m_circles; }
  // Calls f(i) for each circle i that holds (x, y), the largest grids first, until f returns
  // true; returns whether one did.
  template <class F>
  bool any_holding(double x, double y, F f) const {
    for (auto grid = m_grids.rbegin(); grid != m_grids.rend(); ++grid) {
      const auto& [size, buckets] = *grid;
      const long long i = cell(x, size), j = cell(y, size);
      for (long long a = i - 1; a <= i + 1; ++a)
        for (long long b = j - 1; b <= j + 1; ++b) {
          const auto range = buckets.equal_range(key(a, b));
          for (auto it = range.first; it != range.second; ++it) {
            const Circle& c = m_circles[it->second];
            if (std::hypot(x - c.x, y - c.y) < c.r - circle_rounding(c.x, c.y, c.r) &&
                f(it->second))
              return true;
          }
        }
    }
    return false;
  }

 private:
  long long cell(double v, int size) const {
    return static_cast<long long>(std::floor(v / std::ldexp(m_largest, size)));
  }
  static long long key(long long a, long long b) { return a * 1000003LL + b; }
  std::vector<Circle> m_circles;
  double m_largest = 0;
  std::map<int, std::unordered_multimap<long long, std::size_t>> m_grids;
};

// Ends of lines drawn to meet another line but off it by a rounding (a tributary's end
// digitized onto a river's segment, a hair short of it or past it): an end of one of `lines`
// that no other segment shares, within `tolerance` of a vertex of another segment, moves onto
// it; one within `tolerance` of a segment's interior becomes a vertex of that segment. With
// `every`, each vertex of a line does so, not only its ends (lines that cross, or meet, at a
// vertex of one that lies on the other but for a rounding). `tolerance(p)` for the point p, at
// most `spacing`, the width of the cells of the grid that finds the segments. Returns whether
// any point did.
template <class Point_2, class Tolerance>
bool snap_to_other_lines(std::vector<std::vector<Point_2>>& lines, double spacing,
                         const Tolerance& tolerance, bool every = false) {
  const auto x = [](const Point_2& p) { return CGAL::to_double(p.x()); };
  const auto y = [](const Point_2& p) { return CGAL::to_double(p.y()); };
  const auto cell = [&](double c) { return (long long)std::floor(c / spacing); };
  const auto key = [](long long i, long long j) { return i * 1000003LL + j; };
  std::unordered_map<long long, std::vector<std::pair<std::size_t, std::size_t>>> grid;
  for (std::size_t j = 0; j < lines.size(); ++j)
    for (std::size_t k = 0; k + 1 < lines[j].size(); ++k) {
      const Point_2 &p = lines[j][k], &q = lines[j][k + 1];
      const auto samples = std::size_t(2 * std::hypot(x(q) - x(p), y(q) - y(p)) / spacing) + 1;
      long long last = 0;
      for (std::size_t m = 0; m <= samples; ++m) {
        const double t = double(m) / double(samples);
        const long long c = key(cell(x(p) + t * (x(q) - x(p))), cell(y(p) + t * (y(q) - y(p))));
        if (m == 0 || c != last) grid[c].push_back({j, k});
        last = c;
      }
    }
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<double, Point_2>>> added;
  bool moved = false;
  constexpr std::size_t none = std::size_t(-1);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    auto& line = lines[i];
    const std::size_t m = line.size();
    const bool ring = m > 2 && line.front() == line.back();
    if (m < 2 || (ring && !every)) continue;
    for (std::size_t k = 0; k + (ring ? 1 : 0) < m; ++k) {
      if (!every && k != 0 && k + 1 != m) continue;
      Point_2& end = line[k];
      // its own segments and neighbours on its line
      const std::size_t before = k > 0 ? k - 1 : ring ? m - 2 : none, after = k + 1 < m ? k : none;
      const Point_2 previous = before != none ? line[before] : end;
      const Point_2 next = after != none ? line[k + 1] : end;
      bool shared = false;
      const double within = std::min(spacing, tolerance(end));
      double best = within;
      const Point_2* vertex = nullptr;
      std::pair<std::size_t, std::size_t> segment{lines.size(), 0};
      for (long long a = cell(x(end)) - 1; a <= cell(x(end)) + 1; ++a)
        for (long long b = cell(y(end)) - 1; b <= cell(y(end)) + 1; ++b) {
          const auto it = grid.find(key(a, b));
          if (it == grid.end()) continue;
          for (const auto& [j, k] : it->second) {
            if (j == i && (k == before || k == after)) continue;
            const Point_2 &p = lines[j][k], &q = lines[j][k + 1];
            shared = shared || p == end || q == end;
            for (const Point_2* v : {&p, &q}) {
              const double d = std::hypot(x(*v) - x(end), y(*v) - y(end));
              if (d < best && *v != previous && *v != next) best = d, vertex = v;
            }
            const double dx = x(q) - x(p), dy = y(q) - y(p), ll = dx * dx + dy * dy;
            const double t = ((x(end) - x(p)) * dx + (y(end) - y(p)) * dy) / ll;
            const double d = std::abs((x(end) - x(p)) * dy - (y(end) - y(p)) * dx) / std::sqrt(ll);
            if (t > 0 && t < 1 && d < within) segment = {j, k};
          }
        }
      if (shared) continue;
      if (vertex != nullptr) {
        end = *vertex, moved = true;
        if (ring && k == 0) line.back() = end;
      } else if (segment.first < lines.size()) {
        const Point_2& p = lines[segment.first][segment.second];
        added[segment].push_back({std::hypot(x(end) - x(p), y(end) - y(p)), end});
        moved = true;
      }
    }
  }
  for (auto it = added.rbegin(); it != added.rend(); ++it) {  // from the last: indices hold
    auto& [at, points] = *it;
    std::sort(points.begin(), points.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    auto& line = lines[at.first];
    std::vector<Point_2> middle;
    for (const auto& p : points) middle.push_back(p.second);
    line.insert(line.begin() + std::ptrdiff_t(at.second + 1), middle.begin(), middle.end());
  }
  return moved;
}

template <class Point_2>
struct Conforming_network {
  struct Step {
    std::size_t a, b;  // from nodes[a] to nodes[b]
    std::size_t line;  // the input line walked
    bool repeat;       // walked before (lines that overlap): its pair is the earlier one's
    std::size_t u, w;  // the ends of its edge (a part of the line's segment), in its direction
  };
  std::vector<Point_2> nodes;
  std::vector<double> radii;   // of the circle around each node
  std::vector<Step> steps;     // line after line, each in its own direction
  std::vector<Point_2> sites;  // two a step: left of a -> b, then its mirror image on the right
};

// The spacing along the segment u -> w as `spacing_at` (a function of the point) gives it
// where the pairs lie: at each point of the segment its value there, or where it is less than
// two thirds of that at half of it to either side, the least such value (a density that jumps
// at the line asks its own size of each side's cells; one that varies as smoothly as the steps
// may grow, the size on the line, which the cells on both sides share; a point beside outside
// the domain, as `inside` says if not nullptr, is not asked); samples a quarter of it apart, at
// parameters `t` from 0 to 1, and where it drops to less than half within that, on either side of
// the drop a quarter of the smaller spacing apart.
struct Spacing_samples {
  double length = 0;
  std::vector<double> t, h;
};

// \throws std::invalid_argument if the spacing is not positive and finite at a sample, or
// cuts the segment into more than 1e8 steps.
template <class Point_2, class Spacing_at, class Inside = std::nullptr_t>
Spacing_samples sample_spacing(const Point_2& u, const Point_2& w, const Spacing_at& spacing_at,
                               const std::string& who, const Inside& inside = Inside()) {
  const double ux = CGAL::to_double(u.x()), uy = CGAL::to_double(u.y());
  const double dx = CGAL::to_double(w.x()) - ux, dy = CGAL::to_double(w.y()) - uy;
  Spacing_samples s;
  s.length = std::hypot(dx, dy);
  const auto spacing = [&](double t) {
    const double x = ux + t * dx, y = uy + t * dy;
    const double on_line = double(spacing_at(Point_2(x, y)));
    double h = on_line;
    if (!(h > 0) || !std::isfinite(h))
      throw std::invalid_argument(who + ": the spacing at " + to_string(Point_2(x, y)) +
                                  " must be positive and finite, not " + number_to_string(h));
    const double nx = -dy / s.length * h / 2, ny = dx / s.length * h / 2;
    for (const double side : {1.0, -1.0}) {
      const Point_2 q(x + side * nx, y + side * ny);
      if constexpr (!std::is_same_v<Inside, std::nullptr_t>)
        if (!inside(q)) continue;
      const double beside = double(spacing_at(q));
      if (beside > 0 && std::isfinite(beside) && beside < on_line * 2 / 3) h = std::min(h, beside);
    }
    return h;
  };
  s.t = {0.0}, s.h = {spacing(0)};
  for (double steps = 0; s.t.back() < 1;) {
    const double h = s.h.back();
    double next = std::min(1.0, s.t.back() + h / (4 * s.length));
    if (!(next > s.t.back()))  // a spacing below the parameter's rounding
      throw std::invalid_argument(who + ": the spacing " + number_to_string(h) +
                                  " cuts a segment of length " + number_to_string(s.length) +
                                  " into too many steps");
    double h_next = spacing(next);
    if (h_next < h / 2) {  // a drop within the step: found by bisection
      double before = s.t.back(), h_before = h;
      for (int k = 0; k < 64 && (next - before) * s.length > h_next / 4; ++k) {
        const double middle = (before + next) / 2, h_middle = spacing(middle);
        if (!(middle > before && middle < next)) break;
        if (h_middle < h / 2)
          next = middle, h_next = h_middle;
        else
          before = middle, h_before = h_middle;
      }
      if (before > s.t.back()) {
        steps += (before - s.t.back()) * s.length / h;
        s.t.push_back(before);
        s.h.push_back(h_before);
      }
    }
    steps += (next - s.t.back()) * s.length / s.h.back();
    if (!(steps < 1e8))
      throw std::invalid_argument(who + ": the spacing cuts a segment of length " +
                                  number_to_string(s.length) + " into too many steps");
    s.t.push_back(next);
    s.h.push_back(h_next);
  }
  return s;
}

// Steps grow by at most this share of their length from one to the next along a line: a
// spacing that grows faster is lowered (a step twice its neighbour's length would put its
// pair in the circle of the node beyond, and the halving that follows cascades).
constexpr double conforming_spacing_slope = 0.5;

// The cuts of a segment, as parameters from 0 to 1, into at least `least` steps, each about as
// long as the spacing sampled in `s` says where it lies and no longer, that spacing first lowered
// to grow by at most `conforming_spacing_slope` a unit of length from its smaller values along
// the segment and from `at_u` and `at_w` at its ends: as many steps as the integral of 1 /
// spacing along it, rounded up, which the cuts divide into equal parts (the spacing linear
// between samples). A spacing constant along the segment, and not lowered, gives its equal steps.
inline std::vector<double> graded_cuts(Spacing_samples s, std::size_t least, double at_u,
                                       double at_w) {
  const double first = s.h.front();
  const bool constant = std::all_of(s.h.begin(), s.h.end(), [&](double h) { return h == first; });
  const std::size_t n = s.t.size();
  const double g = conforming_spacing_slope * s.length;  // per unit of the parameter
  s.h.front() = std::min(s.h.front(), at_u), s.h.back() = std::min(s.h.back(), at_w);
  for (std::size_t i = 1; i < n; ++i)
    s.h[i] = std::min(s.h[i], s.h[i - 1] + g * (s.t[i] - s.t[i - 1]));
  for (std::size_t i = n - 1; i-- > 0;)
    s.h[i] = std::min(s.h[i], s.h[i + 1] + g * (s.t[i + 1] - s.t[i]));
  std::vector<double> cuts{0.0};
  if (constant && s.h.front() == first && s.h.back() == first) {
    // the equal steps of that length, as for a number (the same bits)
    const auto steps = std::max(least, std::size_t(std::ceil(s.length / first)));
    for (std::size_t j = 1; j <= steps; ++j) cuts.push_back(double(j) / double(steps));
    return cuts;
  }
  std::vector<double> steps_to{0.0};  // the integral up to each sample
  for (std::size_t i = 1; i < n; ++i) {
    const double a = s.h[i - 1], b = s.h[i], along = (s.t[i] - s.t[i - 1]) * s.length;
    steps_to.push_back(steps_to.back() + (std::abs(b - a) > 1e-9 * a
                                              ? along * std::log(b / a) / (b - a)
                                              : along * 2 / (a + b)));
  }
  // (a spacing that fits a whole number of steps is not rounded up to one more)
  const double total = steps_to.back();
  const auto steps = std::max(least, std::size_t(std::ceil(total * (1 - 1e-9))));
  for (std::size_t j = 1, i = 0; j < steps; ++j) {
    const double at = total * double(j) / double(steps);
    while (steps_to[i + 1] < at) ++i;
    // where the integral of 1 / h reaches `at`, h linear from a to b along the interval
    const double a = s.h[i], b = s.h[i + 1], along = (s.t[i + 1] - s.t[i]) * s.length;
    const double in = at - steps_to[i];
    const double x = std::abs(b - a) > 1e-9 * a
                         ? a * along / (b - a) * std::expm1(in * (b - a) / along)
                         : in * (a + b) / 2;
    cuts.push_back(std::min(s.t[i + 1], s.t[i] + x / s.length));
  }
  cuts.push_back(1.0);
  return cuts;
}

// The largest spacing that `spacing_at` gives at the vertices of `lines` and at eight points
// of each segment (1 without lines): the width of the cells that find segments near a point.
// \throws std::invalid_argument as graded_cuts().
template <class Point_2, class Spacing_at>
double largest_spacing(const std::vector<std::vector<Point_2>>& lines, const Spacing_at& spacing_at,
                       const std::string& who) {
  double largest = 0;
  const auto sample = [&](const Point_2& p) {
    const double h = double(spacing_at(p));
    if (!(h > 0) || !std::isfinite(h))
      throw std::invalid_argument(who + ": the spacing at " + to_string(p) +
                                  " must be positive and finite, not " + number_to_string(h));
    largest = std::max(largest, h);
  };
  for (const auto& line : lines)
    for (std::size_t k = 0; k < line.size(); ++k) {
      sample(line[k]);
      if (k + 1 == line.size()) break;
      const double ux = CGAL::to_double(line[k].x()), uy = CGAL::to_double(line[k].y());
      const double dx = CGAL::to_double(line[k + 1].x()) - ux,
                   dy = CGAL::to_double(line[k + 1].y()) - uy;
      for (int j = 1; j < 9; ++j) sample(Point_2(ux + j * dx / 9, uy + j * dy / 9));
    }
  return largest == 0 ? 1.0 : largest;
}

// The network of `lines` at `spacing`, a length or a function of the point. A point that lines
// share (a corner, a junction, a line that ends on another's vertex or segment) is one node,
// whose circle all its steps share. Each edge between nodes is cut into equal steps at most
// `spacing` long, or with a function into steps as long as it says where they lie, lowered
// where it grows faster than half the distance along the lines (graded_cuts()), the segments
// then found through a grid as wide as the largest it gives along the lines, and the roundings
// and the shortest steps below measured by the spacing where they are. At a node where lines
// meet at less than 100 degrees, or three or more meet, the pairs are placed at a prescribed
// angle from each step (0.45 of the narrower sector beside it, at most 45 degrees), so that they
// stay in order around it; elsewhere a node's radius is max(d_{k-1}, d_k)/sqrt(2) of its steps
// (reduced where two circles would not cross), the pairs at about 45 degrees. Then each pair is
// checked against every circle: a step whose pair lies in another node's circle (lines close
// together) is halved, with the steps of that node, down to spacing / 16; one whose circles do
// not cross, with no floor; the steps beside a halved one are kept within twice its length. Up
// to 24 rounds; a pair still inside a circle after that is left (the callers count the
// generators inside circles). With `inside` (a predicate on points), a step whose midpoint or an
// end is inside and a generator of whose pair is not (a line near the boundary or through it)
// is halved too, down to spacing / 16, which brings its pair nearer the line; so are the steps
// of a node whose circle holds one of `obstacles` (the domain's vertices, which cannot move)
// elsewhere than at its centre. `who` opens the messages. \throws std::invalid_argument if
// `spacing` is not positive and finite (a function: at a point sampled), a line has fewer than
//         two points, repeats a point, is cut into too many steps, or two lines (or a line and
//         itself) cross at a point that is a vertex of neither.
template <class Point_2, class Spacing, class Inside = std::nullptr_t>
Conforming_network<Point_2> conforming_network(const std::vector<std::vector<Point_2>>& lines,
                                               const Spacing& spacing, const std::string& who,
                                               const Inside& inside = Inside(),
                                               const std::vector<Point_2>& obstacles = {}) {
  using K = typename CGAL::Kernel_traits<Point_2>::Kernel;
  using CDT = Cvt_triangulation_2<K>;
  using Vertex_handle = typename CDT::Vertex_handle;
  constexpr double pi = 3.14159265358979323846;
  constexpr bool graded = std::is_invocable_v<const Spacing&, const Point_2&>;
  // the largest spacing: the width of the cells that find segments near a point
  const double largest = [&] {
    if constexpr (graded)
      return largest_spacing(lines, spacing, who);
    else
      return double(spacing);
  }();
  if (!(largest > 0) || !std::isfinite(largest))
    throw std::invalid_argument(who + ": the spacing must be positive and finite, not " +
                                number_to_string(largest));
  const auto x = [](const Point_2& p) { return CGAL::to_double(p.x()); };
  const auto y = [](const Point_2& p) { return CGAL::to_double(p.y()); };
  const auto distance = [&](const Point_2& p, const Point_2& q) {
    return std::hypot(x(q) - x(p), y(q) - y(p));
  };
  // the spacing at p: the roundings that join lines and the shortest steps are measured by it
  const auto local = [&](const Point_2& p) {
    if constexpr (graded)
      return double(spacing(p));
    else
      return largest;
  };
  const auto hundredth = [&](const Point_2& p) { return local(p) / 100; };
  const auto line_name = [&](std::size_t i) {
    return lines.size() == 1 ? std::string("the line") : "line " + std::to_string(i);
  };

  // The lines as constraints of a triangulation of their own: it finds the points they share
  // and splits a segment where another line's vertex lies on it (no point is constructed).
  std::vector<std::vector<Point_2>> in = lines;
  CDT cdt;
  std::vector<Point_2> ends;
  std::vector<std::size_t> segment_line;
  const auto triangulate = [&] {
    cdt.clear(), ends.clear(), segment_line.clear();
    // Three points far around the lines first: a triangulation of collinear points is one of
    // dimension 1, where CGAL locates each new point by a walk along all of them.
    double lo_x = HUGE_VAL, lo_y = HUGE_VAL, hi_x = -HUGE_VAL, hi_y = -HUGE_VAL;
    for (const auto& line : in)
      for (const Point_2& p : line)
        lo_x = std::min(lo_x, x(p)), hi_x = std::max(hi_x, x(p)), lo_y = std::min(lo_y, y(p)),
        hi_y = std::max(hi_y, y(p));
    const double size = std::max(hi_x - lo_x, hi_y - lo_y);  // > 0: two points differ
    cdt.insert(Point_2(lo_x - 8 * size, lo_y - 8 * size));
    cdt.insert(Point_2(hi_x + 8 * size, lo_y - 8 * size));
    cdt.insert(Point_2((lo_x + hi_x) / 2, hi_y + 8 * size));
    for (std::size_t i = 0; i < in.size(); ++i) {
      const auto& line = in[i];
      if (line.size() < 2)
        throw std::invalid_argument(who + ": " + line_name(i) + " needs two points at least");
      for (std::size_t k = 0; k + 1 < line.size(); ++k) {
        const double length = distance(line[k], line[k + 1]);
        if (!(length > 0))
          throw std::invalid_argument(who + ": " + line_name(i) + " repeats the point " +
                                      to_string(line[k]));
        ends.push_back(line[k]);
        ends.push_back(line[k + 1]);
        segment_line.push_back(i);
      }
      try {
        std::vector<Vertex_handle> at;  // each point located from the one before
        for (const Point_2& p : line)
          at.push_back(cdt.insert(p, at.empty() ? typename CDT::Face_handle() : at.back()->face()));
        for (std::size_t k = 0; k + 1 < at.size(); ++k) cdt.insert_constraint(at[k], at[k + 1]);
      } catch (const typename CDT::Intersection_of_constraints_exception&) {
        std::vector<std::array<Point_2, 2>> earlier;
        for (std::size_t j = 0; j < i; ++j) add_segments(in[j], false, earlier);
        throw std::invalid_argument(who + ": " +
                                    (in.size() == 1 ? "the line crosses itself"
                                                    : "a line crosses itself or an earlier one") +
                                    " where neither has a vertex" +
                                    first_crossing(earlier, line, false) +
                                    "; give the crossing point as a vertex of both lines");
      }
    }
  };
  for (const auto& line :
       in)  // before snap_to_other_lines() samples them (it only shortens segments)
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
      if (!(distance(line[k], line[k + 1]) / largest < 1e8))
        throw std::invalid_argument(
            who + ": the spacing " + number_to_string(largest) + " cuts a segment of length " +
            number_to_string(distance(line[k], line[k + 1])) + " into too many steps");
  // Vertices of two lines a rounding apart (one line through the other's vertex, or beside it),
  // seen as a short edge between vertices of different lines.
  const auto vertices_apart = [&] {
    int n = 0;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) v->id() = n++;
    std::vector<std::size_t> line_of(std::size_t(n), in.size());
    typename CDT::Face_handle hint;
    for (std::size_t i = 0; i < in.size(); ++i)
      for (const Point_2& p : in[i]) {
        typename CDT::Locate_type lt;
        int li;
        hint = cdt.locate(p, lt, li, hint);
        if (lt == CDT::VERTEX && line_of[std::size_t(hint->vertex(li)->id())] == in.size())
          line_of[std::size_t(hint->vertex(li)->id())] = i;
      }
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
      const auto u = e->first->vertex(CDT::ccw(e->second)),
                 w = e->first->vertex(CDT::cw(e->second));
      const std::size_t a = line_of[std::size_t(u->id())], b = line_of[std::size_t(w->id())];
      if (a != b && a < in.size() && b < in.size() &&
          distance(u->point(), w->point()) < std::min(local(u->point()), local(w->point())) / 100)
        return true;
    }
    return false;
  };
  snap_to_other_lines(in, largest, hundredth);
  try {
    triangulate();
    if (vertices_apart() && snap_to_other_lines(in, largest, hundredth, true)) triangulate();
  } catch (const std::invalid_argument&) {  // a vertex of one a rounding off the other?
    if (!snap_to_other_lines(in, largest, hundredth, true)) throw;
    triangulate();
  }
  Conforming_network<Point_2> net;
  if (in.empty()) return net;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (!cdt.are_there_incident_constraints(v)) continue;  // one of the three far points
    v->id() = int(net.nodes.size());
    net.nodes.push_back(v->point());
  }
  const std::size_t n_nodes = net.nodes.size();

  // The edges between nodes, each once, and each line's walk along them.
  struct Edge {
    std::size_t u, w;
    double length;
  };
  std::vector<Edge> edges;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_of;
  struct Walked {
    std::size_t edge, line;
    bool forward;
  };
  std::vector<Walked> walk;
  for_each_edge_on_input_segments(cdt, ends, [&](Vertex_handle u, Vertex_handle w, std::size_t s) {
    const auto a = std::size_t(u->id()), b = std::size_t(w->id());
    const auto [it, added] = edge_of.emplace(std::minmax(a, b), edges.size());
    if (added) edges.push_back({a, b, distance(net.nodes[a], net.nodes[b])});
    walk.push_back({it->second, segment_line[s], edges[it->second].u == a});
  });

  // Around each node, its edges by angle: the sectors between them, each edge's angle for its
  // pair (end 0 at u, 1 at w), and whether the node's angles are prescribed.
  std::vector<std::vector<std::pair<double, std::size_t>>> around(n_nodes);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Point_2 &u = net.nodes[edges[e].u], &w = net.nodes[edges[e].w];
    around[edges[e].u].push_back({std::atan2(y(w) - y(u), x(w) - x(u)), 2 * e});
    around[edges[e].w].push_back({std::atan2(y(u) - y(w), x(u) - x(w)), 2 * e + 1});
  }
  std::vector<double> angle(2 * edges.size(), pi / 4);
  std::vector<bool> prescribed(n_nodes, false);
  for (std::size_t n = 0; n < n_nodes; ++n) {
    auto& a = around[n];
    std::sort(a.begin(), a.end());
    const std::size_t m = a.size();
    if (m < 2) continue;
    std::vector<double> sector(m);  // from edge k to edge k + 1, counterclockwise
    for (std::size_t k = 0; k < m; ++k)
      sector[k] = k + 1 < m ? a[k + 1].first - a[k].first : a[0].first + 2 * pi - a[k].first;
    double narrowest = 2 * pi;
    for (std::size_t k = 0; k < m; ++k) {
      const double beside = std::min(sector[k], sector[(k + m - 1) % m]);
      angle[a[k].second] = std::min(pi / 4, 0.45 * beside);
      narrowest = std::min(narrowest, beside);
    }
    prescribed[n] = m >= 3 || narrowest < pi * 100 / 180;
  }

  // Each edge's steps, as parameters from u (0) to w (1): equal steps at most `spacing` long
  // (or graded by a function), at least two where an end is prescribed (its next node's radius
  // is), three where both are.
  std::vector<std::vector<double>> cuts(edges.size());
  [[maybe_unused]] std::vector<Spacing_samples> samples;
  // The least spacing at each node that the slope allows from the spacing along the network.
  [[maybe_unused]] std::vector<double> at_node(n_nodes, std::numeric_limits<double>::infinity());
  if constexpr (graded) {
    const double g = conforming_spacing_slope;
    for (const auto& edge : edges) {
      samples.push_back(sample_spacing(net.nodes[edge.u], net.nodes[edge.w], spacing, who, inside));
      const Spacing_samples& s = samples.back();
      for (std::size_t i = 0; i < s.t.size(); ++i) {
        at_node[edge.u] = std::min(at_node[edge.u], s.h[i] + g * s.t[i] * s.length);
        at_node[edge.w] = std::min(at_node[edge.w], s.h[i] + g * (1 - s.t[i]) * s.length);
      }
    }
    // along the edges from the least (Dijkstra's order)
    using Queued = std::pair<double, std::size_t>;
    std::priority_queue<Queued, std::vector<Queued>, std::greater<Queued>> queue;
    for (std::size_t n = 0; n < n_nodes; ++n) queue.push({at_node[n], n});
    while (!queue.empty()) {
      const auto [h, n] = queue.top();
      queue.pop();
      if (h > at_node[n]) continue;
      for (const auto& a : around[n]) {
        const auto& edge = edges[a.second / 2];
        const std::size_t other = a.second % 2 == 0 ? edge.w : edge.u;
        if (h + g * edge.length < at_node[other])
          queue.push({at_node[other] = h + g * edge.length, other});
      }
    }
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const std::size_t least = 1 + prescribed[edges[e].u] + prescribed[edges[e].w];
    if constexpr (graded) {
      cuts[e] = graded_cuts(samples[e], least, at_node[edges[e].u], at_node[edges[e].w]);
    } else {
      const auto steps = std::max(least, std::size_t(std::ceil(edges[e].length / largest)));
      for (std::size_t j = 0; j <= steps; ++j) cuts[e].push_back(double(j) / double(steps));
    }
  }

  struct Step_at {
    std::size_t p, q, edge;
    double length;
  };
  std::vector<Step_at> steps;
  std::vector<std::vector<std::size_t>> ids(edges.size());  // each cut's node
  for (int round = 0;; ++round) {
    // The nodes between the edges' ends, and the steps.
    net.nodes.resize(n_nodes);
    steps.clear();
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Point_2 u = net.nodes[edges[e].u], w = net.nodes[edges[e].w];  // copies: it grows
      const double dx = x(w) - x(u), dy = y(w) - y(u);
      auto& id = ids[e];
      id.assign(cuts[e].size(), 0);
      id.front() = edges[e].u, id.back() = edges[e].w;
      for (std::size_t j = 1; j + 1 < cuts[e].size(); ++j) {
        id[j] = net.nodes.size();
        net.nodes.emplace_back(x(u) + cuts[e][j] * dx, y(u) + cuts[e][j] * dy);
      }
      for (std::size_t j = 0; j + 1 < id.size(); ++j)
        steps.push_back({id[j], id[j + 1], e, distance(net.nodes[id[j]], net.nodes[id[j + 1]])});
    }
    const std::size_t n = net.nodes.size();
    std::vector<std::vector<std::size_t>> steps_at(n);
    for (std::size_t s = 0; s < steps.size(); ++s)
      steps_at[steps[s].p].push_back(s), steps_at[steps[s].q].push_back(s);

    // The radii: max(d)/sqrt(2), or prescribed (fixed).
    auto& r = net.radii;
    r.assign(n, 0.0);
    for (const Step_at& s : steps)
      r[s.p] = std::max(r[s.p], s.length / std::sqrt(2.0)),
      r[s.q] = std::max(r[s.q], s.length / std::sqrt(2.0));
    // At a prescribed node v, the pair of the step to the next node w at the angle a from the
    // step lies on v's circle (radius R) and on w's: |w - v| = d, r_w^2 = R^2 + d^2 - 2Rd cos a.
    // R = min d cos a makes r_w = d sin a where it is least (w's circle as small as it can be,
    // its pair right above it): the pairs of a narrow sector stay far from the other lines.
    std::vector<bool> fixed(n, false);
    const auto next_node = [&](std::size_t end) {
      const auto& id = ids[end / 2];
      return end % 2 == 0 ? id[1] : id[id.size() - 2];
    };
    for (std::size_t v = 0; v < n_nodes; ++v) {
      if (!prescribed[v]) continue;
      double radius = HUGE_VAL;
      for (const auto& around_v : around[v]) {
        const std::size_t end = around_v.second;
        radius = std::min(radius,
                          distance(net.nodes[v], net.nodes[next_node(end)]) * std::cos(angle[end]));
      }
      r[v] = radius, fixed[v] = true;
      for (const auto& around_v : around[v]) {
        const std::size_t end = around_v.second, w = next_node(end);
        const double d = distance(net.nodes[v], net.nodes[w]);
        r[w] = std::sqrt(
            std::max(0.0, radius * radius + d * d - 2 * radius * d * std::cos(angle[end])));
        fixed[w] = true;
      }
    }
    const auto at_prescribed = [&](const Step_at& s) {
      return (s.p < n_nodes && prescribed[s.p]) || (s.q < n_nodes && prescribed[s.q]);
    };
    // Two circles cross if their radii differ by less than the step: the larger free one
    // shrinks to that (never below half its own steps' length, which the smaller already
    // exceeds), or the smaller free one grows where the larger is fixed.
    for (int pass = 0, changed = 1; changed && pass < 100; ++pass) {
      changed = 0;
      for (const Step_at& s : steps) {
        const std::size_t big = r[s.p] >= r[s.q] ? s.p : s.q, small = big == s.p ? s.q : s.p;
        const double most = r[small] + 0.9 * s.length;
        if (r[big] <= most) continue;
        if (!fixed[big])
          r[big] = most, changed = 1;
        else if (!fixed[small])
          r[small] = r[big] - 0.9 * s.length, changed = 1;
      }
    }

    // The pairs, and the steps to halve: those whose circles barely cross, whose pair lies in
    // another circle, and the steps of that circle's node.
    net.sites.assign(2 * steps.size(), Point_2());
    std::vector<bool> halve(steps.size(), false), crossing(steps.size(), false);
    std::vector<Circle_grid::Circle> circles;
    for (std::size_t v = 0; v < n; ++v) circles.push_back({x(net.nodes[v]), y(net.nodes[v]), r[v]});
    Circle_grid grid;
    grid.assign(std::move(circles));
    bool clean = true;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const Step_at& s = steps[k];
      const Point_2 &a = net.nodes[s.p], &b = net.nodes[s.q];
      const double d = s.length, ux = (x(b) - x(a)) / d, uy = (y(b) - y(a)) / d;
      const double along = (r[s.p] * r[s.p] - r[s.q] * r[s.q] + d * d) / (2 * d);
      const double h2 = r[s.p] * r[s.p] - along * along;
      const double h = std::sqrt(std::max(0.0, h2));
      const double mx = x(a) + along * ux, my = y(a) + along * uy;
      net.sites[2 * k] = Point_2(mx - h * uy, my + h * ux);
      net.sites[2 * k + 1] = Point_2(mx + h * uy, my - h * ux);
      // (a prescribed pair is as close to its step as its sector is narrow)
      if (!(h > 0.01 * d) && !at_prescribed(s)) halve[k] = crossing[k] = true, clean = false;
      if constexpr (!std::is_same_v<Inside, std::nullptr_t>) {
        // a step inside, or across the boundary, whose pair is not inside (the line near the
        // boundary, or through it): lower pairs, nearer the line
        const Point_2 m((x(a) + x(b)) / 2, (y(a) + y(b)) / 2);
        if (!(inside(net.sites[2 * k]) && inside(net.sites[2 * k + 1])) &&
            (inside(m) || inside(a) || inside(b)))
          halve[k] = true, clean = false;
      }
      for (int side = 0; side < 2; ++side)
        grid.any_holding(x(net.sites[2 * k + side]), y(net.sites[2 * k + side]), [&](auto v) {
          if (v != s.p && v != s.q) {
            clean = false;
            halve[k] = true;
            for (const std::size_t t : steps_at[v]) halve[t] = true;
          }
          return false;
        });
    }
    // Fixed generators (the domain's vertices) inside a node's circle, not at its centre: the
    // node's steps halved, which shrinks its circle.
    for (const Point_2& f : obstacles)
      grid.any_holding(x(f), y(f), [&](auto v) {
        if (net.nodes[v] != f) {
          clean = false;
          for (const std::size_t t : steps_at[v]) halve[t] = true;
        }
        return false;
      });
    if (clean || round == 24) break;
    // A step no shorter than `spacing` / 16 after halving for a pair in a circle: lines closer
    // than that, or a corner that sharp near its apex, keep their pairs inside circles (the
    // callers say so) rather than get cells far smaller than asked for. Circles that do not
    // cross (a step beside a much shorter one) are graded down to it.
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const double shortest_step =
          local(CGAL::midpoint(net.nodes[steps[k].p], net.nodes[steps[k].q])) / 16;
      halve[k] = halve[k] && (crossing[k] || steps[k].length >= 2 * shortest_step);
    }

    // Halve, then keep the steps beside a halved one within twice its length: along an edge,
    // and among the steps that leave a node (not a prescribed node's first steps, whose pairs
    // are placed for any length of the next).
    for (bool more = true; more;) {
      more = false;
      for (std::size_t v = 0; v < n; ++v) {
        double shortest = HUGE_VAL;
        bool any = false;
        for (const std::size_t s : steps_at[v]) {
          any = any || halve[s];
          shortest = std::min(shortest, steps[s].length / (halve[s] ? 2 : 1));
        }
        if (!any) continue;
        for (const std::size_t s : steps_at[v])
          if (!halve[s] && steps[s].length > 2 * shortest && !at_prescribed(steps[s]))
            halve[s] = true, more = true;
      }
    }
    std::vector<std::vector<double>> finer(edges.size(), std::vector<double>{0.0});
    for (std::size_t e = 0, k = 0; e < edges.size(); ++e) {
      for (std::size_t j = 0; j + 1 < cuts[e].size(); ++j, ++k) {
        if (halve[k]) finer[e].push_back(0.5 * (cuts[e][j] + cuts[e][j + 1]));
        finer[e].push_back(cuts[e][j + 1]);
      }
    }
    cuts = std::move(finer);
  }

  // The steps along each line, in its direction.
  std::vector<bool> walked(steps.size(), false);
  std::vector<std::size_t> first_step(edges.size() + 1, 0);
  for (std::size_t e = 0; e < edges.size(); ++e)
    first_step[e + 1] = first_step[e] + cuts[e].size() - 1;
  std::vector<Point_2> sites;
  for (const Walked& w : walk) {
    const std::size_t m = cuts[w.edge].size() - 1;
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t k = first_step[w.edge] + (w.forward ? j : m - 1 - j);
      const Step_at& s = steps[k];
      const auto& edge = edges[w.edge];
      net.steps.push_back({w.forward ? s.p : s.q, w.forward ? s.q : s.p, w.line, walked[k],
                           w.forward ? edge.u : edge.w, w.forward ? edge.w : edge.u});
      walked[k] = true;
      sites.push_back(net.sites[2 * k + (w.forward ? 0 : 1)]);
      sites.push_back(net.sites[2 * k + (w.forward ? 1 : 0)]);
    }
  }
  net.sites = std::move(sites);
  return net;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_CONFORMING_NETWORK_H
