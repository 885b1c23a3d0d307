// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// conforming_sites_2(): generators mirrored across a line, so that Voronoi faces lie on it;
// insert_conforming_sites_2(): those of several lines, into a marked domain.
#ifndef CVT_2_CONFORMING_SITES_2_H
#define CVT_2_CONFORMING_SITES_2_H

#include <CVT_2/exceptions.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/internal/conforming_network.h>
#include <CVT_2/internal/to_string.h>

#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// The generators that make a polyline *conforming* in a Voronoi diagram: a line that water
/// crosses (a river, a zone border) along which the faces of the cells lie, each perpendicular
/// to the line between the centres of the two cells beside it, as the PEBI grids of reservoir
/// simulation make them (Heinemann et al. 1991; MRST's `pebiGrid`).
template <class Point_2>
struct Conforming_sites {
  /// the points along the line, its vertices among them, at most the spacing apart: the
  /// Voronoi vertices between the pairs
  std::vector<Point_2> nodes;
  /// two generators a segment of `nodes`, `sites[2k]` left of `nodes[k]` -> `nodes[k + 1]` and
  /// `sites[2k + 1]` its mirror image on the right: the face between them is that segment
  std::vector<Point_2> sites;
  /// the radius of the circle around each node that no other generator may enter
  std::vector<double> radii;
};

/// \ingroup PkgCvt2Ref
/// Places, along the polyline `line`, nodes at most `spacing` apart (its vertices, and equal
/// steps on each segment), a circle around each node of radius \f$r_k = \max(d_{k-1},
/// d_k)/\sqrt{2}\f$ (\f$d\f$ the steps; reduced where two neighbouring circles would not
/// cross), and on each step the two points where the circles of its ends cross: a pair of
/// generators mirrored across the step, each at about half a step from it. Both lie on both
/// circles, so the nodes are equidistant from the four generators of the two steps they join:
/// while no other generator lies inside a circle, each node is a vertex of the Voronoi diagram
/// and each step the face between its pair, exactly on the line, perpendicular to the line
/// between the pair. At a corner sharper than 100 degrees, and where the line meets itself, the
/// pairs are placed at a prescribed angle from the steps instead (at most 0.45 of the sector
/// beside them), so that they stay in order around the node; where a pair would fall inside
/// another node's circle (parts of the line close together) the steps there are halved, as
/// `insert_conforming_sites_2()` does for several lines. A node where the line meets itself
/// appears once a visit, with the same circle. Optimizers should keep these generators fixed
/// (`fixed_points`). `spacing` is a length, or a function of the point, as for
/// `insert_conforming_sites_2()`.
/// \throws std::invalid_argument if `spacing` is not positive and finite, the line has fewer
///         than two distinct points or two equal points in a row, or crosses itself at a point
///         that is not one of its vertices.
template <class Point_2, class Spacing>
Conforming_sites<Point_2> conforming_sites_2(const std::vector<Point_2>& line,
                                             const Spacing& spacing) {
  const auto net = internal::conforming_network(std::vector<std::vector<Point_2>>{line}, spacing,
                                                "conforming_sites_2");
  Conforming_sites<Point_2> c;
  for (std::size_t k = 0; k < net.steps.size(); ++k) {
    const auto& s = net.steps[k];
    if (k == 0) c.nodes.push_back(net.nodes[s.a]), c.radii.push_back(net.radii[s.a]);
    c.nodes.push_back(net.nodes[s.b]);
    c.radii.push_back(net.radii[s.b]);
    c.sites.push_back(net.sites[2 * k]);
    c.sites.push_back(net.sites[2 * k + 1]);
  }
  return c;
}

/// \ingroup PkgCvt2Ref
/// The circles of conforming lines (`Conforming_sites::radii` around the nodes), to keep other
/// generators out of: a random start drawn there is drawn again elsewhere
/// (`random_points_in_domain_2()` with `keep_out`), since a free generator at a node is a fixed
/// point of Lloyd's iteration that breaks the line's faces.
template <class Point_2>
class Conforming_disks {
 public:
  /// adds the circles of `c`
  void add(const Conforming_sites<Point_2>& c) {
    auto circles = m_grid.circles();
    for (std::size_t k = 0; k < c.nodes.size(); ++k)
      circles.push_back(
          {CGAL::to_double(c.nodes[k].x()), CGAL::to_double(c.nodes[k].y()), c.radii[k]});
    m_grid.assign(std::move(circles));  // the largest radius may have grown: all again
  }
  /// whether `p` lies inside a circle by more than a rounding (1e-9 of its radius, and 16 units
  /// in the last place of its centre's coordinates: the generators of `Conforming_sites` lie on
  /// the circles)
  bool contains(const Point_2& p) const {
    return containing(CGAL::to_double(p.x()), CGAL::to_double(p.y())) != nullptr;
  }
  bool empty() const { return m_grid.circles().empty(); }  ///< whether there is no circle
  /// whether `p` is the centre of a circle: a node of a line (a vertex of the domain where a
  /// line ends on the boundary, say)
  bool is_node(const Point_2& p) const {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    return m_grid.any_holding(x, y, [&](std::size_t i) {
      return m_grid.circles()[i].x == x && m_grid.circles()[i].y == y;
    });
  }

  /// Where a free generator that moves from `from` toward `to` may go, so that none enters a
  /// circle (the optimizers' named parameter `keep_out`): `to` if it lies in no circle, else
  /// `to` pushed out of the circles it lies in along their radii, else (circles that overlap
  /// too much) `from`.
  Point_2 outside(const Point_2& from, const Point_2& to) const {
    double x = CGAL::to_double(to.x()), y = CGAL::to_double(to.y());
    for (int attempt = 0; attempt < 8; ++attempt) {
      const Disk* d = containing(x, y);
      if (d == nullptr) return attempt == 0 ? to : Point_2(x, y);
      double dx = x - d->x, dy = y - d->y, length = std::hypot(dx, dy);
      if (!(length > 0)) {  // at the centre: out the way it came
        dx = CGAL::to_double(from.x()) - d->x, dy = CGAL::to_double(from.y()) - d->y;
        length = std::hypot(dx, dy);
        if (!(length > 0)) return from;
      }
      const double scale = d->r * (1 + 1e-7) / length;
      x = d->x + dx * scale, y = d->y + dy * scale;
    }
    return containing(x, y) == nullptr ? Point_2(x, y) : from;
  }

 private:
  using Disk = internal::Circle_grid::Circle;
  // the first circle that holds (x, y), the largest first, or null
  const Disk* containing(double x, double y) const {
    const Disk* found = nullptr;
    m_grid.any_holding(x, y, [&](std::size_t i) {
      found = &m_grid.circles()[i];
      return true;
    });
    return found;
  }
  internal::Circle_grid m_grid;
};

/// \ingroup PkgCvt2Ref
/// The two generators mirrored across a step of a conforming line, the line's number and the
/// part of its segment that the step lies on.
template <class Point_2>
struct Conforming_pair_2 {
  Point_2 left, right;  ///< on the left and the right of the step
  std::size_t line;     ///< the number of the line among those given
  /// The part of the line's segment that the step lies on (between the segment's ends,
  /// junctions and points on other lines): its face lies along it, and at the line's free end
  /// runs on past it. Equal: not known (the whole face is the pair's).
  Point_2 from = Point_2(0, 0), to = Point_2(0, 0);
};

/// \ingroup PkgCvt2Ref
/// Inserts into the marked domain of `cdt` the generators that make `lines` conforming at
/// `spacing`, as one network: as `conforming_sites_2()` places them on each line, with one node
/// where lines share a point (a junction, a line that ends on another's vertex or segment), the
/// pairs around a node where three or more lines meet placed as at a sharp corner, and the steps
/// halved where one line's pairs would fall in another's circles. An end of a line within
/// `spacing` / 100 of another line (digitized onto it, a rounding short or past) is moved onto
/// that line's vertex, or made a vertex of its segment. Adds the circles to `disks`; returns
/// the pairs, line after line: a part that lines share is inserted once and listed for each
/// (`Conforming_pair_2::line`). A generator already where a pair goes (a free one, strictly
/// inside: the points of an earlier run) becomes that pair's. A step inside the domain whose
/// pair is not (a line near the boundary) is halved, down to `spacing` / 16, so that its pair,
/// nearer the line, fits. A step whose two generators are still not both strictly inside the
/// domain (in a domain face, or on an edge that is no constraint), or that lies along a
/// constraint (whose faces are there already), is left out, its generators not inserted and
/// its circles not added unless a step kept shares them, and counted in `*left_out` if given.
/// The generators are to stay fixed (`fixed_points`) and the circles free of others
/// (`keep_out(disks)`).
///
/// `spacing` is a length, or a function `double(const Point_2&)` that gives the spacing where
/// the steps lie (the cell size a density asks for, as `Point_refinement_sizing_2` gives it
/// around a well, times `cell_size_scale_2()`): each segment is then cut into steps that follow
/// it where their pairs lie (its value on the line, or half of it to either side where that is
/// less than two thirds of it: a jump), lowered where it grows faster than half the distance
/// along the lines, and the roundings above and the shortest steps are measured by the spacing
/// where they are.
/// \throws std::invalid_argument as `conforming_sites_2()`, if a spacing function gives a value
///         that is not positive and finite, and if two lines cross at a point that is a vertex of
///         neither (the message names the segments).
template <class CDT, class Spacing>
std::vector<Conforming_pair_2<typename CDT::Point_2>> insert_conforming_sites_2(
    CDT& cdt, const std::vector<std::vector<typename CDT::Point_2>>& lines, const Spacing& spacing,
    Conforming_disks<typename CDT::Point_2>& disks, std::size_t* left_out = nullptr) {
  using Point_2 = typename CDT::Point_2;
  typename CDT::Face_handle hint;
  const auto strictly_inside = [&](const Point_2& p) {
    typename CDT::Locate_type lt;
    int li = 0;
    hint = cdt.locate(p, lt, li, hint);
    if (lt == CDT::VERTEX)
      return !cdt.are_there_incident_constraints(hint->vertex(li)) &&
             internal::has_domain_face(cdt, hint->vertex(li));
    if (lt == CDT::EDGE) return !cdt.is_constrained({hint, li}) && hint->is_inside_domain();
    return lt == CDT::FACE && hint->is_inside_domain();
  };
  std::vector<Point_2> fixed;  // the domain's vertices: generators that cannot move away
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (cdt.are_there_incident_constraints(v)) fixed.push_back(v->point());
  const auto net =
      internal::conforming_network(lines, spacing, "conforming lines", strictly_inside, fixed);
  std::vector<Conforming_pair_2<Point_2>> pairs;
  std::vector<Point_2> sites;
  // A step along a constraint (the line given as a barrier or slit too) has its faces already.
  // (its nodes computed: within a rounding of a constrained edge of its midpoint's face, and of
  // that edge's line, not across it)
  const auto on_constraint = [&](const auto& step) {
    const Point_2 &a = net.nodes[step.a], &b = net.nodes[step.b];
    const Point_2 m = CGAL::midpoint(a, b);
    typename CDT::Locate_type lt;
    int li = 0;
    hint = cdt.locate(m, lt, li, hint);
    if (lt == CDT::EDGE && cdt.is_constrained({hint, li})) return true;
    if (lt != CDT::FACE && lt != CDT::EDGE) return false;
    const double rounding =
        internal::circle_rounding(CGAL::to_double(m.x()), CGAL::to_double(m.y()),
                                  std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))));
    for (int i = 0; i < 3; ++i) {
      if (!cdt.is_constrained({hint, i})) continue;
      const typename CDT::Segment s = cdt.segment(hint, i);
      const auto near = [&](const auto& x, const Point_2& p) {
        return std::sqrt(CGAL::to_double(CGAL::squared_distance(x, p))) <= rounding;
      };
      if (near(s, m) && near(s.supporting_line(), a) && near(s.supporting_line(), b)) return true;
    }
    return false;
  };
  // The circles of the nodes of the steps kept: one kept empty for a pair left out would only
  // keep the generators around from their centroids (a line along the boundary, all its steps
  // left out, never converged).
  std::vector<bool> used(net.nodes.size(), false);
  std::size_t out = 0;
  std::map<std::pair<std::size_t, std::size_t>, bool> kept_step;       // by its nodes
  std::set<std::tuple<std::size_t, std::size_t, std::size_t>> listed;  // nodes, line
  for (std::size_t k = 0; k < net.steps.size(); ++k) {
    const auto& s = net.steps[k];
    const Point_2 &left = net.sites[2 * k], &right = net.sites[2 * k + 1];
    const auto nodes = std::minmax(s.a, s.b);
    if (!s.repeat) {
      const bool keep = strictly_inside(left) && strictly_inside(right) && !on_constraint(s);
      kept_step[nodes] = keep;
      if (keep) {
        sites.push_back(left);
        sites.push_back(right);
        used[s.a] = used[s.b] = true;
      } else {
        ++out;
      }
    }
    if (kept_step[nodes] && listed.insert({nodes.first, nodes.second, s.line}).second)
      pairs.push_back({left, right, s.line, net.nodes[s.u], net.nodes[s.w]});
  }
  Conforming_sites<Point_2> kept;
  for (std::size_t v = 0; v < net.nodes.size(); ++v)
    if (used[v]) kept.nodes.push_back(net.nodes[v]), kept.radii.push_back(net.radii[v]);
  disks.add(kept);
  insert_generators_2(cdt, sites);
  if (left_out) *left_out = out;
  return pairs;
}

namespace internal {

// The steps among `pairs` (those of insert_conforming_sites_2(), which lists a part that lines
// share for each): each pair of generators once.
template <class Point_2>
std::size_t number_of_steps(const std::vector<Conforming_pair_2<Point_2>>& pairs) {
  std::set<std::pair<Point_2, Point_2>> steps;
  for (const auto& p : pairs) steps.insert(std::minmax(p.left, p.right));
  return steps.size();
}

// The note on the steps of conforming lines left out (`left_out` of insert_conforming_sites_2(),
// which returned `pairs`), naming by `items` (one a line) the lines that kept none; empty if
// none was left out.
template <class Point_2>
std::string conforming_left_out_note(std::size_t left_out,
                                     const std::vector<Conforming_pair_2<Point_2>>& pairs,
                                     const std::vector<std::int64_t>& items) {
  if (left_out == 0) return {};
  std::vector<bool> kept(items.size(), false);
  for (const auto& p : pairs)
    if (p.line < kept.size()) kept[p.line] = true;
  std::string lost;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (!kept[i]) lost += (lost.empty() ? "" : ", ") + std::to_string(items[i]);
  return std::to_string(left_out) + " of " + std::to_string(left_out + number_of_steps(pairs)) +
         " steps of the conforming lines have a generator outside the domain or lie along a "
         "constraint: left out" +
         (lost.empty() ? "" : "; the lines of items " + lost + " lost all theirs");
}

// The note on the generators of `cdt` inside the circles of conforming lines (after an
// optimization: those that keep_out could not keep away, and those at nodes, as a vertex of
// the domain where a line ends on the boundary), empty if none is.
template <class CDT>
std::string conforming_disks_note(const CDT& cdt,
                                  const Conforming_disks<typename CDT::Point_2>& disks) {
  if (disks.empty()) return {};
  std::size_t inside = 0, on_nodes = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (disks.contains(v->point())) ++(disks.is_node(v->point()) ? on_nodes : inside);
  std::string note;
  if (inside > 0)
    note = std::to_string(inside) +
           " generators lie inside the circles of the conforming lines: the faces near them are "
           "not on the lines";
  if (on_nodes > 0)
    note += (note.empty() ? "" : "; ") + std::to_string(on_nodes) +
            " generators sit on nodes of the conforming lines (vertices of the domain where a "
            "line ends or passes): their cells hold the lines within about half a step of them";
  return note;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_CONFORMING_SITES_2_H
