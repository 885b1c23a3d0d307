// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Constraint_editor_2: insert, extend, move and remove constraints; the diagram stays current.
#ifndef CVT_2_CONSTRAINT_EDITOR_2_H
#define CVT_2_CONSTRAINT_EDITOR_2_H

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/Handle_set.h>
#include <CVT_2/internal/constraint_edits.h>
#include <CVT_2/internal/delaunay_flips.h>
#include <CVT_2/internal/lips.h>
#include <CVT_2/internal/move_vertex.h>
#include <CVT_2/internal/tag_blind_faces.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/natural_neighbor_coordinates_2.h>

#include <CGAL/Kernel/global_functions_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// Edits the inner constraints of a triangulation while its bounded Voronoi diagram stays
/// current, with work local to the edit: cracks that grow, slits inserted, moved and removed
/// (the paper's "constraints [that] move in an unpredictable manner").
///
/// After each edit the blind tags and the domain marks are those a rebuild on the edited
/// triangulation gives (`Bounded_voronoi_diagram_2::update()`), but only these faces are
/// re-tagged: the faces the edit created or changed, the faces the constrained edges around
/// them blind, and the faces the removed or moved edges blinded (a face can be blinded only by
/// a constraint that meets its circumdisk). `report()` says which cells changed.
///
/// Each polyline inserted here gets an id, 0, 1, ... in order; the vertices CGAL inserts on it
/// (where it passes through a vertex, or where another edit's point splits it) join it. The
/// domain's own constraints have no id: they are never removed, but their vertices can move.
/// Constraints inserted here lie in the closed domain and meet other constraints only at
/// vertices (or end on them: the point is inserted there, no intersection is constructed); an
/// edit that would break these rules is an error that names both, and changes nothing.
/// \tparam CDT as for `Bounded_voronoi_diagram_2`, with CGAL's default
///         `No_constraint_intersection_requiring_constructions_tag` or a stricter one.
/// \tparam Traits as for `Bounded_voronoi_diagram_2`.
template <class CDT, class Traits = Bvd_traits_2<typename CDT::Geom_traits>>
class Constraint_editor_2 {
 public:
  using Diagram = Bounded_voronoi_diagram_2<CDT, Traits>;  ///< the diagram kept current
  using Point_2 = typename CDT::Point_2;                   ///< a point
  using FT = typename CDT::Geom_traits::FT;                ///< a number
  using Vertex_handle = typename CDT::Vertex_handle;       ///< a vertex, a cell
  using Face_handle = typename CDT::Face_handle;           ///< a face
  using Constraint_id = std::size_t;                       ///< a polyline inserted here

  /// The weights that carry a field over to one lip of a new vertex (`lip` as in
  /// `natural_neighbor_matrix_2()`'s `lips(true)`: the wedges of the domain between its
  /// constraints, counterclockwise).
  struct Carried_lip {
    Vertex_handle vertex;                               ///< a vertex the edit inserted
    int lip;                                            ///< which of its lips
    std::vector<std::pair<Vertex_handle, FT>> weights;  ///< normalized; empty if it sees none
  };

  /// What an edit changed.
  struct Edit_report {
    /// the vertices whose cell changed (the rows a solver assembles again), new ones included
    std::vector<Vertex_handle> changed_cells;
    /// the vertices an insertion or an extension inserted, in order (a move inserts none: the
    /// vertex it returns is the one moved, under a new handle if it was removed and inserted)
    std::vector<Vertex_handle> new_vertices;
    std::size_t retagged_faces = 0;  ///< the faces whose blind tag was computed again
    /// With `carry_weights(true)`, for each vertex an insertion or an extension inserted (in
    /// the order of `new_vertices`): its Sibson coordinates in the diagram before the edit,
    /// normalized, which carry a field over to it (empty outside the closed domain), from
    /// both sides of the new constraint.
    std::vector<std::vector<std::pair<Vertex_handle, FT>>> carried_weights;
    /// The same for each lip of the new vertices that have two or more (along a crack, not at
    /// its tip): the weights of the nodes that the lip sees, and of those joined to the vertex
    /// by a constraint, normalized again, so that a field that jumps across the new crack
    /// takes on each lip the values of its side only.
    std::vector<Carried_lip> carried_lips;
  };

  /// An editor of `cdt`, whose diagram `diagram` is (`diagram.triangulation()` is `cdt`).
  Constraint_editor_2(CDT& cdt, Diagram& diagram) : m_cdt(cdt), m_diagram(diagram) {
    if (&diagram.triangulation() != &cdt)
      throw std::invalid_argument("Constraint_editor_2: the diagram is not the triangulation's");
  }

  /// Whether insertions and extensions fill `Edit_report::carried_weights` (a natural-neighbour
  /// query a new vertex, before the edit); default false.
  void carry_weights(bool b) { m_carry = b; }

  /// Inserts the polyline through `points` (at least two distinct points; a repeated point in a
  /// row counts once; a last point equal to the first closes it) as a new constraint and
  /// returns its id.
  /// \throws Domain_error if a point lies outside the domain, or a segment leaves the domain,
  ///         crosses or overlaps another constraint or the polyline itself.
  template <class PointRange>
  Constraint_id insert_constraint(const PointRange& points) {
    std::vector<Point_2> path;
    for (const Point_2& p : points) {
      if (!internal::is_valid_point(p))
        throw Domain_error("insert_constraint: " +
                           internal::invalid_point_message("point " + internal::to_string(p)));
      if (path.empty() || path.back() != p) path.push_back(p);
    }
    if (path.size() < 2)
      throw Domain_error("insert_constraint: a constraint needs two distinct points");
    const Constraint_id id = m_polylines.size();
    check_path(path, [id] { return "the new constraint " + std::to_string(id); });
    const auto weights = old_weights(path, 0);
    begin_edit();
    m_polylines.emplace_back();
    m_removed.push_back(false);
    std::vector<Vertex_handle> vertices;
    for (std::size_t k = 0; k < path.size(); ++k) {
      vertices.push_back(
          insert_point(path[k], vertices.empty() ? Face_handle() : vertices.back()->face()));
      carry(weights, k);
    }
    m_polylines[id].push_back(vertices.front());
    for (std::size_t i = 0; i + 1 < vertices.size(); ++i)
      insert_segment(id, vertices[i], vertices[i + 1]);
    finish_edit();
    return id;
  }

  /// Extends constraint `id` from its last vertex to `tip` (a crack that grows), with vertices
  /// at most `spacing` apart along the new piece if `spacing` is positive (0: none). A tip on
  /// another constraint is inserted on it.
  /// \throws Domain_error as `insert_constraint()`, if `id` was removed or is unknown, or if
  ///         `spacing` is negative or NaN.
  void extend_constraint(Constraint_id id, const Point_2& tip, FT spacing = FT(0)) {
    check_id(id, "extend_constraint");
    if (!(spacing >= FT(0)))
      throw Domain_error("extend_constraint: a spacing of " +
                         internal::number_to_string(CGAL::to_double(spacing)) +
                         " (a positive length, or 0 for no vertices on the way)");
    if (!internal::is_valid_point(tip))
      throw Domain_error("extend_constraint: " +
                         internal::invalid_point_message("tip " + internal::to_string(tip)));
    const Point_2 from = m_polylines[id].back()->point();
    if (tip == from) {
      begin_edit();
      finish_edit();
      return;
    }
    std::vector<Point_2> path{from};
    const double length = std::sqrt(CGAL::to_double(CGAL::squared_distance(from, tip)));
    const double h = CGAL::to_double(spacing);
    if (h > 0 && !(length / h <= 1e6))
      throw Domain_error("extend_constraint: a spacing of " + internal::number_to_string(h) +
                         " would put more than a million vertices on the way");
    const std::size_t pieces = h > 0 ? std::size_t(std::ceil(length / h)) : 1;
    for (std::size_t k = 1; k < pieces; ++k) {
      const double t = double(k) / double(pieces);
      path.emplace_back(from.x() + t * (tip.x() - from.x()), from.y() + t * (tip.y() - from.y()));
    }
    path.push_back(tip);
    check_path(
        path, [id] { return "the extension of constraint " + std::to_string(id); },
        m_polylines[id].back()->face());
    const auto weights = old_weights(path, 1);
    begin_edit();
    Vertex_handle previous = m_polylines[id].back();
    for (std::size_t k = 1; k < path.size(); ++k) {
      const Vertex_handle v = insert_point(path[k], previous->face());
      carry(weights, k);
      insert_segment(id, previous, v);
      previous = v;
    }
    finish_edit();
  }

  /// Moves the constrained vertex `v` to `to`; its constraints follow, and the free generators
  /// stay where they are (those the moved edges sweep over end up on their other side). If
  /// the edges can follow without sweeping over a vertex, the vertex moves within its star,
  /// edges flipping behind it, and keeps its handle; otherwise it is removed and inserted
  /// again, and the handle returned is the new one.
  /// \throws Domain_error if `v` is not constrained, is on the convex hull, if another vertex
  ///         is at `to`, or if an edge of `v` would then cross or run along another
  ///         constraint, or (but for a vertex of the domain's boundary) leave the domain.
  Vertex_handle move_constrained_vertex(Vertex_handle v, const Point_2& to) {
    const std::string what = "move_constrained_vertex: " + internal::to_string(v->point());
    if (!m_cdt.are_there_incident_constraints(v)) throw Domain_error(what + " is on no constraint");
    if (!internal::is_valid_point(to))
      throw Domain_error(what + ": " +
                         internal::invalid_point_message("target " + internal::to_string(to)));
    bool boundary = false;
    auto fc = m_cdt.incident_faces(v), done = fc;
    do {
      if (m_cdt.is_infinite(fc))
        throw Domain_error(what + " is on the convex hull, which an editor does not move");
      boundary = boundary || !fc->is_inside_domain();
    } while (++fc != done);
    if (to == v->point()) {
      begin_edit();
      finish_edit();
      return v;
    }
    typename CDT::Locate_type lt;
    int li;
    m_cdt.locate(to, lt, li, v->face());
    if (lt == CDT::VERTEX)
      throw Domain_error(what + " cannot go to " + internal::to_string(to) +
                         ": another vertex is there");
    std::vector<Edge> incident;
    m_cdt.incident_constraints(v, std::back_inserter(incident));
    std::vector<Vertex_handle> ends;
    for (const Edge& e : incident) {
      const Vertex_handle x = e.first->vertex(CDT::ccw(e.second)) == v
                                  ? e.first->vertex(CDT::cw(e.second))
                                  : e.first->vertex(CDT::ccw(e.second));
      ends.push_back(x);
      internal::check_segment(
          m_cdt, x->point(), to,
          [&](Vertex_handle a, Vertex_handle b) { return constraint_name(a, b); },
          [&] { return what + " cannot go to " + internal::to_string(to); }, v, !boundary,
          x->face());
    }
    for (std::size_t i = 0; i < ends.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (internal::pieces_meet(ends[i]->point(), to, to, ends[j]->point(), true))
          throw Domain_error(what + " cannot go to " + internal::to_string(to) +
                             ": two of its edges would overlap");
    begin_edit();
    for (const Edge& e : incident) blinded_before(e);
    const Point_2 from = v->point();
    if (slide(v, to)) {
      finish_edit(v);
      return v;
    }
    slide(v, from);  // back the way it came, then the long way
    if (boundary) {
      finish_edit(v);
      throw Domain_error(what + " cannot go to " + internal::to_string(to) +
                         ": its edges would sweep over vertices, which a vertex of the domain's "
                         "boundary does not do yet");
    }
    const Vertex_handle w = reinsert(v, to, ends);
    finish_edit(w);
    return w;
  }

  /// Removes constraint `id`: its edges are no longer constrained (no other constraint shares
  /// them: overlaps are refused), and its vertices stay, as free generators where no other
  /// constraint holds them.
  /// \throws Domain_error if `id` was removed or is unknown.
  void remove_constraint(Constraint_id id) {
    check_id(id, "remove_constraint");
    begin_edit();
    const auto& vertices = m_polylines[id];
    std::vector<internal::Flip_candidate<CDT>> stack;
    std::vector<typename CDT::Edge> edges;
    for (std::size_t i = 0; i + 1 < vertices.size(); ++i) {
      Face_handle f;
      int k = 0;
      if (!m_cdt.is_edge(vertices[i], vertices[i + 1], f, k))
        throw std::logic_error("remove_constraint: a constraint edge is missing");
      edges.emplace_back(f, k);
    }
    for (const auto& e : edges) blinded_before(e);
    for (const auto& [f, k] : edges) {
      m_edge_owner.erase(key(Edge(f, k)));
      m_modified.push_back(f);
      m_modified.push_back(f->neighbor(k));
      lift(f, k, stack);
    }
    flip(stack);
    m_removed[id] = true;
    finish_edit();
  }

  /// the vertices of constraint `id`, in order along it, the first again at the end of a closed
  /// one (a removed one's: the vertices it had, where they are now, as later edits and moves
  /// left them)
  /// \throws Domain_error if there is no constraint `id`
  const std::vector<Vertex_handle>& vertices_in_constraint(Constraint_id id) const {
    check_known(id, "vertices_in_constraint");
    return m_polylines[id];
  }
  /// whether constraint `id` was removed
  /// \throws Domain_error if there is no constraint `id`
  bool is_removed(Constraint_id id) const {
    check_known(id, "is_removed");
    return m_removed[id];
  }
  /// the number of constraints inserted here, removed ones included (the next id)
  std::size_t number_of_constraints() const { return m_polylines.size(); }
  /// what the last edit changed (one that threw changed nothing and leaves it as it was)
  const Edit_report& report() const { return m_report; }

 private:
  using Edge = typename CDT::Edge;
  using Edge_key = std::pair<Vertex_handle, Vertex_handle>;

  static Edge_key key(Vertex_handle a, Vertex_handle b) {
    return b < a ? Edge_key(b, a) : Edge_key(a, b);
  }
  static Edge_key key(const Edge& e) {
    return key(e.first->vertex(CDT::ccw(e.second)), e.first->vertex(CDT::cw(e.second)));
  }

  void check_known(Constraint_id id, const char* what) const {
    if (id >= m_polylines.size())
      throw Domain_error(std::string(what) + ": there is no constraint " + std::to_string(id));
  }
  void check_id(Constraint_id id, const char* what) const {
    check_known(id, what);
    if (m_removed[id])
      throw Domain_error(std::string(what) + ": constraint " + std::to_string(id) + " was removed");
  }

  // The name of the constrained edge (a, b) in an error.
  std::string constraint_name(Vertex_handle a, Vertex_handle b) const {
    const auto it = m_edge_owner.find(key(a, b));
    const std::string where =
        " (" + internal::to_string(a->point()) + " - " + internal::to_string(b->point()) + ")";
    return it == m_edge_owner.end() ? "a constraint of the domain" + where
                                    : "constraint " + std::to_string(it->second) + where;
  }

  // Checks, before anything changes, that the polyline `path` can be inserted: every piece
  // lies in the closed domain and meets the constraints and the other pieces only at vertices
  // or at its own ends (internal::check_segment).
  template <class What>
  void check_path(const std::vector<Point_2>& path, const What& what,
                  Face_handle hint = Face_handle()) const {
    const auto name = [&](Vertex_handle a, Vertex_handle b) { return constraint_name(a, b); };
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      internal::check_segment(m_cdt, path[i], path[i + 1], name, what, Vertex_handle(), true, hint);
      for (std::size_t j = 0; j < i; ++j)
        if (j + 1 == i ? internal::pieces_meet(path[j], path[j + 1], path[i], path[i + 1], true)
            : j == 0 && i + 2 == path.size() && path[0] == path[i + 1]  // a closed polyline
                ? internal::pieces_meet(path[i], path[i + 1], path[0], path[1], true)
                : internal::pieces_meet(path[j], path[j + 1], path[i], path[i + 1], false))
          throw Domain_error(what() + " crosses itself: " + internal::to_string(path[j]) + " - " +
                             internal::to_string(path[j + 1]) + " and " +
                             internal::to_string(path[i]) + " - " +
                             internal::to_string(path[i + 1]));
    }
  }

  using Weights = std::vector<std::pair<Vertex_handle, FT>>;

  // With carry_weights(true), the Sibson coordinates of path[first...] in the diagram as it is.
  std::vector<Weights> old_weights(const std::vector<Point_2>& path, std::size_t first) const {
    std::vector<Weights> out(m_carry ? path.size() : 0);
    for (std::size_t k = first; k < out.size(); ++k) {
      const auto r =
          CVT_2::natural_neighbor_coordinates_2(m_diagram, path[k], std::back_inserter(out[k]));
      if (!r.third || r.second == 0) out[k].clear();
      for (auto& [v, w] : out[k]) w /= r.second;
    }
    return out;
  }
  // Notes path[k]'s weights in the report if insert_point() just inserted a vertex there.
  void carry(const std::vector<Weights>& weights, std::size_t k) {
    if (m_carry && m_report.carried_weights.size() < m_report.new_vertices.size())
      m_report.carried_weights.push_back(weights[k]);
  }

  void begin_edit() {
    m_report = Edit_report();
    m_modified.clear();
    m_before.clear();
  }

  // The faces the constrained edge e blinds now, to tag again after the edit (e goes or moves).
  void blinded_before(const Edge& e) {
    internal::faces_blinded_by(m_cdt, m_diagram.geom_traits(), e, m_before, m_seen, m_stack);
  }

  // Inserts p (a vertex already there is returned as is), marks the new faces' domain flag as
  // the face or the side of the edge p was in, and splits the constraint p lies on, if any.
  Vertex_handle insert_point(const Point_2& p, Face_handle hint = Face_handle()) {
    typename CDT::Locate_type lt;
    int li;
    const Face_handle f = m_cdt.locate(p, lt, li, hint);
    if (lt == CDT::VERTEX) return f->vertex(li);
    // check_path() made sure that p is in the closed domain
    Vertex_handle a, b;
    bool split = false, left = false, right = false, inside = false;
    if (lt == CDT::EDGE && f->is_constrained(li)) {
      split = true;
      a = f->vertex(CDT::ccw(li)), b = f->vertex(CDT::cw(li));  // f is left of a -> b
      const Face_handle n = f->neighbor(li);
      left = !m_cdt.is_infinite(f) && f->is_inside_domain();
      right = !m_cdt.is_infinite(n) && n->is_inside_domain();
    } else {
      inside = !m_cdt.is_infinite(f) && f->is_inside_domain();
    }
    const Vertex_handle v = m_cdt.insert(p, lt, f, li);
    const auto orientation = m_cdt.geom_traits().orientation_2_object();
    auto fc = m_cdt.incident_faces(v), done = fc;
    do {
      m_modified.push_back(fc);
      if (m_cdt.is_infinite(fc)) {
        fc->set_inside_domain(false);
      } else if (split) {
        const int i = fc->index(v);
        const int side =
            int(orientation(a->point(), b->point(), fc->vertex(CDT::ccw(i))->point())) +
            int(orientation(a->point(), b->point(), fc->vertex(CDT::cw(i))->point()));
        fc->set_inside_domain(side > 0 ? left : right);
      } else {
        fc->set_inside_domain(inside);
      }
    } while (++fc != done);
    if (split) {
      const auto owner = m_edge_owner.find(key(a, b));
      if (owner != m_edge_owner.end()) {
        const Constraint_id id = owner->second;
        m_edge_owner.erase(owner);
        auto& line = m_polylines[id];
        for (std::size_t i = 0; i + 1 < line.size(); ++i)
          if (key(line[i], line[i + 1]) == key(a, b)) {
            line.insert(line.begin() + std::ptrdiff_t(i) + 1, v);
            break;
          }
        m_edge_owner[key(a, v)] = id;
        m_edge_owner[key(v, b)] = id;
      }
    }
    m_report.new_vertices.push_back(v);
    return v;
  }

  // The constrained edge i of f is no longer constrained; its flip goes on `stack`.
  void lift(Face_handle f, int i, std::vector<internal::Flip_candidate<CDT>>& stack) {
    const Face_handle n = f->neighbor(i);
    f->set_constraint(i, false);
    n->set_constraint(n->index(f), false);
    stack.push_back(internal::Flip_candidate<CDT>::of(f, i));
  }

  // Lawson's flips from `stack`, the flipped faces noted as changed.
  void flip(std::vector<internal::Flip_candidate<CDT>>& stack) {
    internal::lawson_flips(m_cdt, stack, [&](Face_handle f, Face_handle g) {
      m_modified.push_back(f);
      m_modified.push_back(g);
    });
  }

  // CGAL's insertion of the constrained segment from u to w: the faces it made into `created`,
  // they and the faces beside its edges noted as changed; returns the vertices along it, which
  // CGAL split it at, from u to w.
  std::vector<Vertex_handle> constrain(Vertex_handle u, Vertex_handle w,
                                       std::vector<Face_handle>& created) {
    created.clear();
    static_cast<typename CDT::Ctr&>(m_cdt).insert_constraint(u, w, std::back_inserter(created));
    m_modified.insert(m_modified.end(), created.begin(), created.end());
    std::vector<Vertex_handle> chain{u};
    while (chain.back() != w) chain.push_back(internal::next_along(m_cdt, chain.back(), w));
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      Face_handle f;
      int k = 0;
      if (m_cdt.is_edge(chain[i], chain[i + 1], f, k)) {
        m_modified.push_back(f);
        m_modified.push_back(f->neighbor(k));
      }
    }
    return chain;
  }

  // Inserts the constrained segment from the last vertex of constraint `id`, u, to w, through
  // the vertices on it, which join the constraint; gives the new faces their domain flag.
  void insert_segment(Constraint_id id, Vertex_handle u, Vertex_handle w) {
    if (u == w) return;
    auto& created = m_stack;  // free between walks
    const std::vector<Vertex_handle> chain = constrain(u, w, created);
    std::vector<Edge_key> chain_keys;
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      chain_keys.push_back(key(chain[i], chain[i + 1]));
      m_edge_owner[chain_keys.back()] = id;
      m_polylines[id].push_back(chain[i + 1]);
    }
    if (created.empty()) return;  // an edge there already: no new face
    m_seen.clear();
    for (const Face_handle f : created) m_seen.insert(f);
    internal::flood_domain_marks(m_cdt, m_seen, [&](Face_handle f, int i) {
      const Edge_key k = key(f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i)));
      return std::find(chain_keys.begin(), chain_keys.end(), k) != chain_keys.end();
    });
  }

  // The move of v to `to` when its edges would sweep over vertices: its constraints to the
  // vertices `ends` are lifted, v is removed and inserted at `to`, and the constraints go
  // back, each in its polyline. The new faces' domain flags flood from the old faces around.
  Vertex_handle reinsert(Vertex_handle v, const Point_2& to,
                         const std::vector<Vertex_handle>& ends) {
    std::vector<std::optional<Constraint_id>> owners;
    std::vector<internal::Flip_candidate<CDT>> stack;
    for (const Vertex_handle x : ends) {
      const auto it = m_edge_owner.find(key(v, x));
      owners.push_back(it == m_edge_owner.end() ? std::nullopt : std::optional(it->second));
      if (it != m_edge_owner.end()) m_edge_owner.erase(it);
      Face_handle f;
      int k = 0;
      if (!m_cdt.is_edge(v, x, f, k))
        throw std::logic_error("move_constrained_vertex: a constrained edge is missing");
      lift(f, k, stack);
    }
    flip(stack);  // constrained Delaunay again before CGAL removes v (its hole filling expects it)
    // the faces around the link but v's own keep their domain marks (a hole next to v's)
    std::vector<Vertex_handle> link;
    internal::Handle_set<Face_handle> kept;
    internal::link_and_kept_faces(m_cdt, v, link, kept);
    m_cdt.remove(v);
    for (const Vertex_handle x : link) note_star(x);  // the faces of the hole among them
    const Vertex_handle w = insert_point(to);
    internal::Handle_set<Face_handle> made;  // faces made since, which may reuse kept ones
    auto fc = m_cdt.incident_faces(w), fdone = fc;
    do made.insert(fc);
    while (++fc != fdone);
    for (auto& line : m_polylines) std::replace(line.begin(), line.end(), v, w);
    std::vector<Face_handle> created;
    for (std::size_t i = 0; i < ends.size(); ++i) {
      const std::vector<Vertex_handle> chain = constrain(ends[i], w, created);
      for (const Face_handle f : created) made.insert(f);
      if (!owners[i]) continue;
      for (std::size_t j = 0; j + 1 < chain.size(); ++j)
        m_edge_owner[key(chain[j], chain[j + 1])] = *owners[i];
      // the vertices on the way join the polyline, between ends[i] and w
      auto& line = m_polylines[*owners[i]];
      for (std::size_t j = 0; j + 1 < line.size(); ++j) {
        const bool forward = line[j] == ends[i] && line[j + 1] == w;
        if (!forward && !(line[j] == w && line[j + 1] == ends[i])) continue;
        std::vector<Vertex_handle> inner(chain.begin() + 1, chain.end() - 1);
        if (!forward) std::reverse(inner.begin(), inner.end());
        line.insert(line.begin() + std::ptrdiff_t(j) + 1, inner.begin(), inner.end());
        break;
      }
    }
    const auto& faces = m_cdt.tds().faces();
    internal::Handle_set<Face_handle> fresh;
    for (const Face_handle f : m_modified)
      if (faces.is_used(f)) fresh.insert(f);
    internal::flood_domain_marks(
        m_cdt, fresh,
        [&](Face_handle f, int i) {
          return m_edge_owner.count(key(f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i)))) != 0;
        },
        [&](Face_handle f) { return kept.contains(f) && !made.contains(f); });
    m_report.new_vertices.clear();  // w is v moved, not a vertex the edit inserted
    return w;
  }

  // Moves v to `to` by steps within its star, with Lawson's flips after each; false if it
  // gets stuck (an edge of v would have to cross a vertex or a constraint).
  bool slide(Vertex_handle v, const Point_2& to) {
    std::vector<internal::Flip_candidate<CDT>> stack;
    for (int step = 0; step < 200 && v->point() != to; ++step) {
      note_star(v);
      const double done = internal::move_free_vertex(m_cdt, v, to);
      note_star(v);
      auto fc = m_cdt.incident_faces(v), end = fc;
      do
        for (int i = 0; i < 3; ++i) stack.push_back(internal::Flip_candidate<CDT>::of(fc, i));
      while (++fc != end);
      flip(stack);
      if (done == 0) return false;
    }
    return v->point() == to;
  }

  void note_star(Vertex_handle v) {
    auto fc = m_cdt.incident_faces(v), done = fc;
    do m_modified.push_back(fc);
    while (++fc != done);
  }

  // Tags again the faces the edit can have changed and fills the report; `moved` is the vertex
  // a move moved (its edges' tags change though their vertices do not).
  void finish_edit(Vertex_handle moved = Vertex_handle()) {
    const auto& faces = m_cdt.tds().faces();
    m_alive.clear();
    m_region.clear();
    for (const Face_handle f : m_modified)
      if (faces.is_used(f)) m_alive.insert(f);
    for (const Face_handle f : m_before)
      if (faces.is_used(f)) m_region.insert(f);
    // the faces the constrained edges around the changed faces blind: their tag may be stale
    m_edges.clear();
    for (const Face_handle f : m_alive)
      for (int i = 0; i < 3; ++i)
        if (f->is_constrained(i)) m_edges.emplace_back(key(Edge(f, i)), Edge(f, i));
    std::sort(m_edges.begin(), m_edges.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < m_edges.size(); ++i)
      if (i == 0 || m_edges[i].first != m_edges[i - 1].first)
        internal::faces_blinded_by(m_cdt, m_diagram.geom_traits(), m_edges[i].second, m_region,
                                   m_seen, m_stack);
    // the tags of the old faces before, by their edges' vertices; one whose edge's face the
    // edit changed (gone, or another edge at that index now) counts as changed
    m_old.clear();
    for (const Face_handle f : m_region)
      if (!m_alive.contains(f)) {
        if (!f->is_blinded()) {
          m_old.emplace_back(f, Edge_key());
        } else if (faces.is_used(f->blinding_edge().first) &&
                   !m_alive.contains(f->blinding_edge().first)) {
          m_old.emplace_back(f, key(f->blinding_edge()));
        } else {
          m_old.emplace_back(f, Edge_key(m_cdt.infinite_vertex(), m_cdt.infinite_vertex()));
        }
      }
    for (const Face_handle f : m_alive) m_region.insert(f);
    internal::retag_faces(m_cdt, m_diagram.geom_traits(), m_region, m_seen, m_stack);
    m_changed.clear();
    const auto add_face = [&](Face_handle f) {
      for (int i = 0; i < 3; ++i)
        if (!m_cdt.is_infinite(f->vertex(i))) m_changed.push_back(f->vertex(i));
    };
    for (const Face_handle f : m_alive) add_face(f);
    for (const auto& [f, was] : m_old) {
      const Edge_key now = f->is_blinded() ? key(f->blinding_edge()) : Edge_key();
      if (now != was || (moved != Vertex_handle() && (now.first == moved || now.second == moved)))
        add_face(f);
    }
    const auto by_point = [](Vertex_handle a, Vertex_handle b) { return a->point() < b->point(); };
    std::sort(m_changed.begin(), m_changed.end(), by_point);
    m_changed.erase(std::unique(m_changed.begin(), m_changed.end()), m_changed.end());
    m_report.changed_cells.assign(m_changed.begin(), m_changed.end());
    m_report.retagged_faces = m_region.size();
    if (m_carry) split_lips();
  }

  // The carried weights of each new vertex with two lips or more, split by lip: a node counts
  // on the lip it is seen from, or on both beside a constraint it lies on the line of
  // (internal::lips_toward()).
  void split_lips() {
    for (std::size_t k = 0; k < m_report.carried_weights.size(); ++k) {
      const Vertex_handle v = m_report.new_vertices[k];
      const int lips = internal::number_of_lips(m_cdt, v);
      if (lips < 2) continue;
      const std::size_t first = m_report.carried_lips.size();
      for (int lip = 0; lip < lips; ++lip) m_report.carried_lips.push_back({v, lip, {}});
      for (const auto& [x, w] : m_report.carried_weights[k])
        internal::lips_toward(m_cdt, v, x->point(), [&, x = x, w = w](int lip) {
          m_report.carried_lips[first + std::size_t(lip)].weights.emplace_back(x, w);
        });
      for (std::size_t l = first; l < m_report.carried_lips.size(); ++l) {
        auto& weights = m_report.carried_lips[l].weights;
        FT sum = 0;
        for (const auto& xw : weights) sum += xw.second;
        for (auto& xw : weights) xw.second /= sum;
      }
    }
  }

  CDT& m_cdt;
  Diagram& m_diagram;
  std::vector<std::vector<Vertex_handle>> m_polylines;
  std::vector<bool> m_removed;
  std::map<Edge_key, Constraint_id> m_edge_owner;  // the edges of the constraints made here
  Edit_report m_report;
  bool m_carry = false;
  std::vector<Face_handle> m_modified;  // faces the edit created or changed (some may be gone)
  internal::Handle_set<Face_handle> m_before;  // faces blinded by edges that went or moved
  // scratch of finish_edit() and the walks
  internal::Handle_set<Face_handle> m_alive, m_region, m_seen;
  std::vector<Face_handle> m_stack;
  std::vector<std::pair<Edge_key, Edge>> m_edges;
  std::vector<std::pair<Face_handle, Edge_key>> m_old;
  std::vector<Vertex_handle> m_changed;
};

}  // namespace CVT_2

#endif  // CVT_2_CONSTRAINT_EDITOR_2_H
