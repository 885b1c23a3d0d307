// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Virtual_insertion: the bounded Voronoi diagram as it would be with one more point, without
// inserting it: what natural-neighbour coordinates are made of.
#ifndef CVT_2_INTERNAL_VIRTUAL_INSERTION_H
#define CVT_2_INTERNAL_VIRTUAL_INSERTION_H

#include <CVT_2/internal/circumcenter_filters.h>
#include <CVT_2/internal/construct_cell.h>
#include <CVT_2/internal/tag_blind_faces.h>
#include <CVT_2/mark_domain_2.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/enum.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// Inserting a point q into a constrained Delaunay triangulation removes its conflict zone (the
// domain faces whose circumcircles hold q, connected to q's face through unconstrained edges)
// and fills it with the star of q: a face (q, s, t) for each edge (s, t) of the zone's rim. This
// class finds the zone and the star, tags the star's faces blind as Algorithm 1 would (a walk
// along each face's way from its centroid to its circumcenter, through the star and the faces
// around it, to the first constraint it meets), and gives the fans Algorithm 2 walks: around q,
// and around each rim vertex before and after the insertion. The triangulation is not changed,
// so queries may run at once on several threads, each with its own Virtual_insertion.
//
// A q on a constrained edge (a, b) splits it: the star has a gap there, its edges (q, a) and
// (q, b) are constrained, halves of (a, b).
template <class Diagram>
class Virtual_insertion {
 public:
  using CDT = typename Diagram::Triangulation;
  using Traits = typename Diagram::Geom_traits;
  using Point_2 = typename CDT::Point_2;
  using FT = typename CDT::Geom_traits::FT;
  using Vertex_handle = typename CDT::Vertex_handle;  // the null handle stands for q
  using Face_handle = typename CDT::Face_handle;
  using Edge = typename CDT::Edge;
  using Type = typename Diagram::Cell_vertex::Type;

  // A constrained edge by its ends; a half of the edge q splits keeps that whole edge, which it
  // is the same constraint as (one straight barrier), but not the other half.
  struct Constraint {
    Vertex_handle a, b, whole_a, whole_b;
  };

  // A face of the star: (q, s, t), counterclockwise; `inner` is the face of the zone whose edge
  // `index` is the rim edge (s, t).
  struct Star_face {
    Vertex_handle s, t;
    Face_handle inner;
    int index;
    bool rim_constrained;     // the rim edge (s, t) is a constraint
    bool constrained_after;   // (q, t) is a half of the split constraint
    bool constrained_before;  // (q, s) is
    bool blind = false;
    Constraint blinding;
    Point_2 center;  // the circumcenter of (q, s, t)
  };

  enum Location { OUTSIDE, ON_VERTEX, INSIDE };

  explicit Virtual_insertion(const Diagram& diagram)
      : m_cdt(&diagram.triangulation()),
        m_traits(diagram.geom_traits()),
        m_circumcenter(m_traits.construct_circumcenter_2_object()),
        m_clip_point(m_traits.construct_clip_point_2_object()) {}

  // Queries on another diagram (of the same type), the buffers kept.
  void attach(const Diagram& diagram) {
    m_cdt = &diagram.triangulation();
    m_traits = diagram.geom_traits();
    m_circumcenter = m_traits.construct_circumcenter_2_object();
    m_clip_point = m_traits.construct_clip_point_2_object();
  }

  // Inserts q virtually; `hint` (updated) is a face near q. OUTSIDE: q is not in the closed
  // domain; ON_VERTEX: q is a vertex, vertex(); INSIDE: the star is built.
  Location insert(const Point_2& q, Face_handle& hint);

  const Point_2& query() const { return m_q; }
  Vertex_handle vertex() const { return m_vertex; }
  const std::vector<Star_face>& star() const { return m_star; }
  // A zone has 4 faces on average: a linear search; a large one (cocircular points) is sorted.
  bool in_conflict(Face_handle f) const {
    if (m_sorted.empty())
      return std::find(m_conflict.begin(), m_conflict.end(), f) != m_conflict.end();
    return std::binary_search(m_sorted.begin(), m_sorted.end(), f, less_face);
  }
  const Point_2& point(Vertex_handle v) const { return v == Vertex_handle() ? m_q : v->point(); }

  // The fans, as internal::fan_chain() reads them.
  class Query_fan;     // around q
  class Neighbor_fan;  // around a rim vertex, before or after the insertion

  // The circumcenter of a face of the triangulation, built once a query.
  const Point_2& circumcenter(Face_handle f) const {
    for (const auto& [g, c] : m_centers)
      if (g == f) return c;
    m_centers.emplace_back(
        f, m_circumcenter(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
    return m_centers.back().second;
  }

  // The rim vertices, each once, in the order of the star: q's natural neighbours.
  const std::vector<Vertex_handle>& rim() const { return m_rim; }

  bool same(const Constraint& x, const Constraint& y) const {
    const bool x_half = x.a == Vertex_handle() || x.b == Vertex_handle();
    const bool y_half = y.a == Vertex_handle() || y.b == Vertex_handle();
    if (x_half && y_half) return ends_equal(x.a, x.b, y.a, y.b);
    return ends_equal(x.whole_a, x.whole_b, y.whole_a, y.whole_b);
  }
  Constraint real_constraint(const Edge& e) const {
    const Vertex_handle a = e.first->vertex(CDT::ccw(e.second));
    const Vertex_handle b = e.first->vertex(CDT::cw(e.second));
    return {a, b, a, b};
  }
  Constraint half(Vertex_handle end) const { return {Vertex_handle(), end, m_split_a, m_split_b}; }

 private:
  static bool less_face(Face_handle f, Face_handle g) { return &*f < &*g; }
  static bool ends_equal(Vertex_handle a, Vertex_handle b, Vertex_handle c, Vertex_handle d) {
    return (a == c && b == d) || (a == d && b == c);
  }
  void find_conflict_zone(const std::vector<Face_handle>& seeds);
  void add_to_zone(Face_handle f) {
    constexpr std::size_t small = 32;
    m_conflict.push_back(f);
    if (m_conflict.size() < small) return;
    if (m_sorted.empty()) {
      m_sorted = m_conflict;
      std::sort(m_sorted.begin(), m_sorted.end(), less_face);
    } else {
      m_sorted.insert(std::upper_bound(m_sorted.begin(), m_sorted.end(), f, less_face), f);
    }
  }
  bool build_star();
  // Algorithm 1 on the star (tag_star_face()) and its steps.
  class Way;
  struct Triangle;
  void tag_star_face(Star_face& face) const;
  bool sees_circumcenter_nearby(const Star_face& face) const;
  void walk_to_circumcenter(Star_face& face) const;
  int exit_edge(const Triangle& t, int entered, const Way& way,
                std::optional<Vertex_handle>& through) const;
  Triangle star_triangle(int k) const;
  Triangle real_triangle(Face_handle f) const;
  bool is_constrained(const Triangle& t, int i) const;
  Constraint constraint(const Triangle& t, int i) const;
  Triangle across(const Triangle& t, int i) const;
  bool constraint_at(Vertex_handle x, Constraint& out) const;

  const CDT* m_cdt;
  Traits m_traits;
  decltype(std::declval<const Traits&>().construct_circumcenter_2_object()) m_circumcenter;
  decltype(std::declval<const Traits&>().construct_clip_point_2_object()) m_clip_point;
  mutable std::vector<std::pair<Face_handle, Point_2>> m_centers;
  Point_2 m_q;
  Vertex_handle m_vertex;
  Edge m_split;                         // the constrained edge q lies on, if any
  Vertex_handle m_split_a, m_split_b;   // its ends
  std::vector<Face_handle> m_conflict;  // the zone, as found
  std::vector<Face_handle> m_sorted;    // the zone sorted by address, once it is large
  std::vector<Star_face> m_star;        // around q, counterclockwise
  std::vector<Vertex_handle> m_rim;
  std::vector<std::pair<Face_handle, int>> m_stack;  // find_conflict_zone()'s: edges to visit
  std::vector<Face_handle> m_seeds;
  std::vector<Star_face> m_edges;  // build_star()'s
  std::vector<char> m_used;
};

template <class Diagram>
auto Virtual_insertion<Diagram>::insert(const Point_2& q, Face_handle& hint) -> Location {
  m_q = q;
  m_vertex = Vertex_handle();
  m_split = Edge();
  m_split_a = m_split_b = Vertex_handle();
  m_conflict.clear();
  m_star.clear();
  m_rim.clear();
  m_centers.clear();
  if (m_cdt->dimension() < 2) return OUTSIDE;
  typename CDT::Locate_type lt;
  int li;
  Face_handle f = m_cdt->locate(q, lt, li, hint);
  hint = f;
  // On an edge, which of its faces comes back depends on the hint, and the sums run around q
  // from it: the face whose opposite vertex comes first in xy order, for the same bits whatever
  // the query before.
  if (lt == CDT::EDGE && !m_cdt->is_infinite(f->neighbor(li))) {
    const int mi = m_cdt->mirror_index(f, li);
    const Face_handle g = f->neighbor(li);
    if (m_cdt->is_infinite(f) || g->vertex(mi)->point() < f->vertex(li)->point()) f = g, li = mi;
  }
  std::vector<Face_handle>& seeds = m_seeds;
  seeds.clear();
  switch (lt) {
    case CDT::VERTEX:
      m_vertex = f->vertex(li);
      return has_domain_face(*m_cdt, m_vertex) ? ON_VERTEX : OUTSIDE;
    case CDT::FACE:
      if (!f->is_inside_domain()) return OUTSIDE;
      seeds.push_back(f);
      break;
    case CDT::EDGE: {
      const Face_handle g = f->neighbor(li);
      if (f->is_inside_domain()) seeds.push_back(f);
      if (g->is_inside_domain() && !m_cdt->is_infinite(g)) seeds.push_back(g);
      if (seeds.empty()) return OUTSIDE;
      if (f->is_constrained(li)) {
        m_split = Edge(f, li);
        m_split_a = f->vertex(CDT::ccw(li));
        m_split_b = f->vertex(CDT::cw(li));
      }
      break;
    }
    default:
      return OUTSIDE;
  }
  find_conflict_zone(seeds);
  if (!build_star()) return OUTSIDE;  // not reached on a valid triangulation
  for (Star_face& s : m_star) {
    s.center = m_circumcenter(q, point(s.s), point(s.t));
    tag_star_face(s);
  }
  return INSIDE;
}

// The domain faces whose circumcircles hold q (perturbed as CGAL's insertion is), connected to
// the seeds through unconstrained edges; a seed holds q on its closure. Depth first, each face's
// edges counterclockwise from the one it was entered by: the zone is a triangulated polygon with
// all its vertices on its rim, so the rim edges (constrained, or to a face not in conflict) come
// out in order around q, into m_edges, but for the constraint q splits.
template <class Diagram>
void Virtual_insertion<Diagram>::find_conflict_zone(const std::vector<Face_handle>& seeds) {
  const bool split = m_split.first != Face_handle();
  // Without a split, the second seed (q on the edge they share) is found in conflict from the
  // first: the rim's order runs through it.
  m_conflict.assign(seeds.begin(), split ? seeds.end() : seeds.begin() + 1);
  m_sorted.clear();
  m_edges.clear();
  m_stack.clear();
  for (std::size_t k = m_conflict.size(); k-- > 0;)
    for (const int i : {2, 1, 0}) m_stack.emplace_back(m_conflict[k], i);
  while (!m_stack.empty()) {
    const auto [f, i] = m_stack.back();
    m_stack.pop_back();
    const Face_handle n = f->neighbor(i);
    const bool constrained = f->is_constrained(i);
    // The in-circle test first: a face not in conflict (most) needs no search of the zone.
    if (!constrained && !m_cdt->is_infinite(n) && n->is_inside_domain() &&
        m_cdt->side_of_oriented_circle(n, m_q, true) == CGAL::ON_POSITIVE_SIDE) {
      if (!in_conflict(n)) {
        add_to_zone(n);
        const int j = n->index(f);
        m_stack.emplace_back(n, CDT::cw(j));
        m_stack.emplace_back(n, CDT::ccw(j));
      }
      continue;
    }
    const Vertex_handle s = f->vertex(CDT::ccw(i)), t = f->vertex(CDT::cw(i));
    if (split && ends_equal(s, t, m_split_a, m_split_b)) continue;  // not a rim edge
    Star_face& e = m_edges.emplace_back();
    e.s = s, e.t = t, e.inner = f, e.index = i;
    e.rim_constrained = constrained;
    e.constrained_after = e.constrained_before = false;
  }
}

// The rim of the zone, counterclockwise around q, as faces of the star; with a split
// constraint, each side's chain from one end of it to the other.
template <class Diagram>
bool Virtual_insertion<Diagram>::build_star() {
  std::vector<Star_face>& edges = m_edges;
  const bool split = m_split.first != Face_handle();
  if (!split) {  // as found, if they close a cycle (they do on a valid triangulation)
    bool cycle = !edges.empty();
    bool simple = true;  // each rim vertex once: no constraint on the rim to turn around
    for (std::size_t k = 0; k < edges.size() && cycle; ++k) {
      cycle = edges[k].t == edges[k + 1 == edges.size() ? 0 : k + 1].s;
      simple = simple && !edges[k].rim_constrained;
    }
    if (cycle) {
      m_star.swap(edges);
      for (const Star_face& s : m_star)
        if (simple || std::find(m_rim.begin(), m_rim.end(), s.s) == m_rim.end())
          m_rim.push_back(s.s);
      return true;
    }
  }
  // Chains: a rim edge follows the one that ends where it starts. With a split, the chains
  // start at the rim edges that start at an end of the split constraint.
  const auto next_of = [&](Vertex_handle t) {
    for (std::size_t k = 0; k < edges.size(); ++k)
      if (edges[k].s == t) return k;
    return edges.size();
  };
  std::vector<char>& used = m_used;
  used.assign(edges.size(), 0);
  const auto follow = [&](std::size_t k) {
    while (k < edges.size() && !used[k]) {
      used[k] = 1;
      m_star.push_back(edges[k]);
      if (split && (edges[k].t == m_split_a || edges[k].t == m_split_b)) return;  // a chain ends
      k = next_of(edges[k].t);
    }
  };
  if (!split) {
    if (edges.empty()) return false;
    follow(0);
  } else {
    for (const Vertex_handle end : {m_split_b, m_split_a}) {
      const std::size_t k = next_of(end);
      if (k == edges.size() || used[k]) continue;
      const std::size_t first = m_star.size();
      follow(k);
      m_star[first].constrained_before = true;
      m_star.back().constrained_after = true;
    }
  }
  if (m_star.size() != edges.size()) return false;
  for (const Star_face& s : m_star)
    if (std::find(m_rim.begin(), m_rim.end(), s.s) == m_rim.end()) m_rim.push_back(s.s);
  for (const Star_face& s : m_star)
    if (std::find(m_rim.begin(), m_rim.end(), s.t) == m_rim.end()) m_rim.push_back(s.t);
  return true;
}

// Algorithm 1 for one face of the star: the first constraint that its way [g, c), from the
// centroid to the circumcenter, meets (the paper's P, as Bvd_traits_2::Is_blinded_2 asks it of
// one constraint; the first, as Compare_blinding_distance_2 orders two). Tagging the whole
// triangulation, tag_blind_faces() starts from each constraint; for one face, a walk along the
// way through the triangles it crosses finds the first constraint directly (the tests compare
// the two on q inserted). Most faces need no walk: their circumcenter is in them or just across
// an open edge.
template <class Diagram>
void Virtual_insertion<Diagram>::tag_star_face(Star_face& face) const {
  face.blind = false;
  if (!sees_circumcenter_nearby(face)) walk_to_circumcenter(face);
}

// The common cases, sure in floating point from the points alone: c in the face (no angle
// obtuse); or c in the triangle across one unconstrained edge, a star face or one of the
// triangulation: with one angle obtuse (at most one is) and the others acute, the centroid and
// the circumcenter project into the edge opposite it, so the way crosses that open edge.
template <class Diagram>
bool Virtual_insertion<Diagram>::sees_circumcenter_nearby(const Star_face& face) const {
  const Point_2& p0 = m_q;
  const Point_2& p1 = point(face.s);
  const Point_2& p2 = point(face.t);
  CGAL::Sign angle[3];  // at q, s, t: c beyond the rim edge, (t, q), (q, s) if negative
  if (!angle_signs(p0, p1, p2, angle)) return false;
  // The exit edge (a, b) (the face on its left, w its third vertex) and x, the third vertex of
  // the triangle across it, if that edge is not constrained.
  const std::size_t n = m_star.size(), k = std::size_t(&face - m_star.data());
  const Point_2 *a = nullptr, *b = nullptr, *w = nullptr, *x = nullptr;
  if (angle[1] == CGAL::NEGATIVE) {
    const Star_face& next = m_star[(k + 1) % n];
    if (!face.constrained_after && next.s == face.t) a = &p2, b = &p0, w = &p1, x = &point(next.t);
  } else if (angle[2] == CGAL::NEGATIVE) {
    const Star_face& previous = m_star[(k + n - 1) % n];
    if (!face.constrained_before && previous.t == face.s)
      a = &p0, b = &p1, w = &p2, x = &point(previous.s);
  } else if (angle[0] == CGAL::NEGATIVE) {
    if (face.rim_constrained) return false;
    const Face_handle out = face.inner->neighbor(face.index);
    if (!m_cdt->is_infinite(out) && out->is_inside_domain())
      a = &p1, b = &p2, w = &p0, x = &out->vertex(out->index(face.inner))->point();
  } else {
    return true;  // c in the face
  }
  // c, beyond (a, b), in the triangle (b, a, x): left of a -> x, right of b -> x ((b, a, w) is
  // clockwise)
  return a != nullptr && is_circumcenter_surely_left(*a, *b, *w, *x) &&
         is_circumcenter_surely_left(*b, *a, *w, *x);
}

// The way [g, c) of a star face, as the walk asks it: Approximate_dual_segment_2 from the
// circumcenter already built; where it is unsure (rarely), the traits' Dual_segment_2, built at
// the first such question.
template <class Diagram>
class Virtual_insertion<Diagram>::Way {
 public:
  Way(const Traits& traits, const Point_2& p, const Point_2& q, const Point_2& r, const Point_2& c)
      : m_traits(traits), m_p0(p), m_p1(q), m_p2(r), m_approximate(p, q, r, c) {}
  // The sign of orientation(a, b, c): negative where c lies beyond the directed edge (a, b).
  CGAL::Sign side_of_circumcenter(const Point_2& a, const Point_2& b) const {
    CGAL::Sign s;
    return m_approximate.side_of_circumcenter(a, b, s) ? s : exact().side_of_circumcenter(a, b);
  }
  // The sign of orientation(g, c, x): where x lies from the way.
  CGAL::Sign side_of_point(const Point_2& x) const {
    CGAL::Sign s;
    return m_approximate.side_of_point(x, s) ? s : exact().side_of_point(x);
  }

 private:
  using Dual_segment = decltype(std::declval<const Traits&>().construct_dual_segment_2_object()(
      std::declval<const Point_2&>(), std::declval<const Point_2&>(),
      std::declval<const Point_2&>()));
  [[gnu::noinline]] const Dual_segment& exact() const {
    if (!m_exact) m_exact.emplace(m_traits.construct_dual_segment_2_object()(m_p0, m_p1, m_p2));
    return *m_exact;
  }
  const Traits& m_traits;
  const Point_2 &m_p0, &m_p1, &m_p2;
  Approximate_dual_segment_2<Point_2> m_approximate;
  mutable std::optional<Dual_segment> m_exact;
};

// A triangle the way crosses: a face of the star or of the triangulation, its vertices
// counterclockwise (the null handle is q). Its edge i is opposite v[i]; for a star face, edge 0
// is the rim edge, 1 is (t, q), 2 is (q, s).
template <class Diagram>
struct Virtual_insertion<Diagram>::Triangle {
  Vertex_handle v[3];
  int star;  // the face of the star, or -1
  Face_handle real;
};

template <class Diagram>
auto Virtual_insertion<Diagram>::star_triangle(int k) const -> Triangle {
  const Star_face& s = m_star[std::size_t(k)];
  return Triangle{{Vertex_handle(), s.s, s.t}, k, Face_handle()};
}

template <class Diagram>
auto Virtual_insertion<Diagram>::real_triangle(Face_handle f) const -> Triangle {
  return Triangle{{f->vertex(0), f->vertex(1), f->vertex(2)}, -1, f};
}

template <class Diagram>
bool Virtual_insertion<Diagram>::is_constrained(const Triangle& t, int i) const {
  if (t.star < 0) return t.real->is_constrained(i);
  const Star_face& s = m_star[std::size_t(t.star)];
  return i == 0 ? s.rim_constrained : i == 1 ? s.constrained_after : s.constrained_before;
}

// \pre is_constrained(t, i)
template <class Diagram>
auto Virtual_insertion<Diagram>::constraint(const Triangle& t, int i) const -> Constraint {
  if (t.star < 0) return real_constraint(Edge(t.real, i));
  const Star_face& s = m_star[std::size_t(t.star)];
  return i == 0 ? real_constraint(Edge(s.inner, s.index)) : half(i == 1 ? s.t : s.s);
}

// The triangle across edge i of t, in the triangulation with q: a face of the zone is replaced
// by the face of the star on the same edge.
template <class Diagram>
auto Virtual_insertion<Diagram>::across(const Triangle& t, int i) const -> Triangle {
  const int n = int(m_star.size());
  if (t.star >= 0) {
    const Star_face& s = m_star[std::size_t(t.star)];
    if (i == 0) return real_triangle(s.inner->neighbor(s.index));
    return star_triangle(i == 1 ? (t.star + 1) % n : (t.star + n - 1) % n);
  }
  const Face_handle f = t.real->neighbor(i);
  if (!t.real->is_constrained(i) && in_conflict(f)) {
    const Vertex_handle a = t.real->vertex(CDT::cw(i)), b = t.real->vertex(CDT::ccw(i));
    for (int k = 0; k < n; ++k)
      if (m_star[std::size_t(k)].s == a && m_star[std::size_t(k)].t == b) return star_triangle(k);
  }
  return real_triangle(f);
}

// Which constraint ends at vertex x, in the triangulation with q: the halves at q or at an end of
// the split constraint, the others as they are (a tie at x: the first by its far end); false if
// none does.
template <class Diagram>
bool Virtual_insertion<Diagram>::constraint_at(Vertex_handle x, Constraint& out) const {
  bool found = false;
  const auto consider = [&](const Constraint& c, Vertex_handle far) {
    if (!found || CGAL::compare_xy(point(far), point(out.a == x ? out.b : out.a)) == CGAL::SMALLER)
      out = c, found = true;
  };
  if (x == Vertex_handle()) {
    if (m_split_a != Vertex_handle())
      consider(half(m_split_a), m_split_a), consider(half(m_split_b), m_split_b);
    return found;
  }
  if (x == m_split_a || x == m_split_b) consider(half(x), Vertex_handle());
  auto ec = m_cdt->incident_edges(x), done = ec;
  do {
    const Edge e = *ec;
    if (!m_cdt->is_constrained(e)) continue;
    const Constraint c = real_constraint(e);
    if (ends_equal(c.a, c.b, m_split_a, m_split_b)) continue;  // split: its halves count
    consider(c, c.a == x ? c.b : c.a);
  } while (++ec != done);
  return found;
}

// Where the way leaves triangle t, not by the edge it `entered` by (-1: none): the edge c lies
// beyond that the way crosses (between two such edges, the side of the vertex they share says
// which), and into `through` a vertex of that edge the way goes through, if it does; -1 if c is
// in t or on its boundary (seen).
template <class Diagram>
int Virtual_insertion<Diagram>::exit_edge(const Triangle& t, int entered, const Way& way,
                                          std::optional<Vertex_handle>& through) const {
  through.reset();
  int candidates[2], n = 0;
  for (int i = 0; i < 3; ++i)
    if (i != entered && way.side_of_circumcenter(point(t.v[(i + 1) % 3]),
                                                 point(t.v[(i + 2) % 3])) == CGAL::NEGATIVE)
      candidates[n++] = i;
  if (n == 0) return -1;
  int exit = candidates[0];
  if (n == 2) {  // c beyond the vertex x the two edges share
    const int i = candidates[0], j = candidates[1], x = 3 - i - j;
    // The edge opposite i runs v[i+1] -> v[i+2]; the way leaves through the one whose first end
    // is on its left and second on its right.
    const auto leaves = [&](int e) {
      return way.side_of_point(point(t.v[(e + 1) % 3])) != CGAL::NEGATIVE &&
             way.side_of_point(point(t.v[(e + 2) % 3])) != CGAL::POSITIVE;
    };
    if (way.side_of_point(point(t.v[x])) == CGAL::ZERO) through = t.v[x];
    exit = leaves(i) ? i : j;
  }
  if (!through)
    for (const int e : {(exit + 1) % 3, (exit + 2) % 3})
      if (way.side_of_point(point(t.v[e])) == CGAL::ZERO) through = t.v[e];
  return exit;
}

// The walk along the way of a star face, from the face itself, until c is reached (seen) or a
// constraint is met: one crossed, or one that ends at a vertex the way goes through (the
// segments are closed, as for Is_blinded_2). On a constrained Delaunay triangulation the way
// meets no vertex before a constraint (each point of [g, c) is strictly inside the face's
// circumcircle, where the face sees no vertex), nor comes back into the star.
template <class Diagram>
void Virtual_insertion<Diagram>::walk_to_circumcenter(Star_face& face) const {
  const Way way(m_traits, m_q, point(face.s), point(face.t), face.center);
  Triangle t = star_triangle(int(&face - m_star.data()));
  int entered = -1;
  // a bound against a loop that cannot be (the TDS counts its faces; Triangulation_2 would
  // circulate the hull to leave the infinite ones out)
  const std::size_t most = 4 * (m_cdt->tds().number_of_faces() + m_star.size()) + 16;
  std::optional<Vertex_handle> through;
  for (std::size_t steps = 0; steps < most; ++steps) {
    const int exit = exit_edge(t, entered, way, through);
    if (exit < 0) return;
    if (is_constrained(t, exit)) {
      face.blind = true;
      face.blinding = constraint(t, exit);
      return;
    }
    if (through && constraint_at(*through, face.blinding)) {
      face.blind = true;
      return;
    }
    // Into the triangle across the exit edge, entered through its edge of the same two ends.
    const Vertex_handle ea = t.v[(exit + 1) % 3], eb = t.v[(exit + 2) % 3];
    t = across(t, exit);
    entered = -1;
    for (int i = 0; i < 3; ++i)
      if (ends_equal(t.v[(i + 1) % 3], t.v[(i + 2) % 3], ea, eb)) entered = i;
    if (t.star < 0 && (m_cdt->is_infinite(t.real) || !t.real->is_inside_domain()))
      return;  // left the domain without a constraint: not reached on a marked domain
  }
}

// The faces of the star around q, as fan_chain() reads them.
template <class Diagram>
class Virtual_insertion<Diagram>::Query_fan {
 public:
  using Vertex = Vertex_handle;
  using Constraint = typename Virtual_insertion::Constraint;
  using Point_2 = typename Virtual_insertion::Point_2;
  using Type = typename Virtual_insertion::Type;

  explicit Query_fan(const Virtual_insertion& vi) : m_vi(vi) {}

  std::size_t size() const { return m_vi.m_star.size(); }
  bool starts_wedges() const { return m_vi.m_split_a != Vertex_handle(); }
  bool inside(std::size_t) const { return true; }
  bool blind(std::size_t j) const { return face(j).blind; }
  Constraint blinding(std::size_t j) const { return face(j).blinding; }
  const Point_2& circumcenter(std::size_t j) const { return face(j).center; }
  Vertex after(std::size_t j) const { return face(j).t; }
  Vertex before(std::size_t j) const { return face(j).s; }
  Constraint edge_after(std::size_t j) const { return m_vi.half(face(j).t); }
  Constraint edge_before(std::size_t j) const { return m_vi.half(face(j).s); }
  bool constrained_after(std::size_t j) const { return face(j).constrained_after; }
  bool same(const Constraint& a, const Constraint& b) const { return m_vi.same(a, b); }
  Point_2 clip_point(Vertex w, const Constraint& c) const {
    return m_vi.m_clip_point(m_vi.m_q, m_vi.point(w), m_vi.point(c.a), m_vi.point(c.b));
  }
  Point_2 midpoint(Vertex w) const { return CGAL::midpoint(m_vi.m_q, m_vi.point(w)); }
  const Point_2& generator() const { return m_vi.m_q; }

 private:
  const Star_face& face(std::size_t j) const { return m_vi.m_star[j]; }
  const Virtual_insertion& m_vi;
};

// The faces around a rim vertex i, as fan_chain() reads them: before the insertion, its faces
// in the triangulation; after, the run of them in the zone replaced by the faces of the star at
// i, (q, i, t) then (q, s, i); from a face that follows a constraint if i has one.
template <class Diagram>
class Virtual_insertion<Diagram>::Neighbor_fan {
 public:
  using Vertex = Vertex_handle;
  using Constraint = typename Virtual_insertion::Constraint;
  using Point_2 = typename Virtual_insertion::Point_2;
  using Type = typename Virtual_insertion::Type;

  Neighbor_fan(const Virtual_insertion& vi, Vertex_handle i, bool after_insertion)
      : m_vi(vi), m_i(i) {
    // The faces around i, from one out of the zone, the run in the zone replaced.
    boost::container::small_vector<Face_handle, 16> around;
    auto fc = vi.m_cdt->incident_faces(i), done = fc;
    do around.push_back(fc);
    while (++fc != done);
    std::size_t start = 0;
    while (start < around.size() && vi.in_conflict(around[start])) ++start;
    bool replaced = false;
    for (std::size_t n = 0; n < around.size(); ++n) {
      const Face_handle f = around[(start + n) % around.size()];
      if (!after_insertion || !vi.in_conflict(f)) {
        m_entries.push_back({f, f->index(i), -1});
      } else if (!replaced) {
        replaced = true;
        for (std::size_t k = 0; k < vi.m_star.size(); ++k)
          if (vi.m_star[k].s == i) m_entries.push_back({Face_handle(), 0, int(k)});
        for (std::size_t k = 0; k < vi.m_star.size(); ++k)
          if (vi.m_star[k].t == i) m_entries.push_back({Face_handle(), 0, int(k)});
      }
    }
    for (std::size_t j = 0; j < m_entries.size() && !m_wedges; ++j)
      if (constrained_before_entry(j)) m_wedges = true, m_first = j;
  }

  std::size_t size() const { return m_entries.size(); }
  bool starts_wedges() const { return m_wedges; }
  bool inside(std::size_t j) const {
    return entry(j).star >= 0 || entry(j).real->is_inside_domain();
  }
  bool blind(std::size_t j) const {
    return entry(j).star >= 0 ? star(j).blind : entry(j).real->is_blinded();
  }
  Constraint blinding(std::size_t j) const {
    return entry(j).star >= 0 ? star(j).blinding
                              : m_vi.real_constraint(entry(j).real->blinding_edge());
  }
  const Point_2& circumcenter(std::size_t j) const {
    return entry(j).star >= 0 ? star(j).center : m_vi.circumcenter(entry(j).real);
  }
  // Whether face j's circumcenter is the same before and after the insertion.
  bool stable(std::size_t j) const { return entry(j).star < 0 && !m_vi.in_conflict(entry(j).real); }
  // For (q, i, t): before t, after q; for (q, s, i): before q, after s.
  Vertex after(std::size_t j) const {
    const Entry& e = entry(j);
    if (e.star < 0) return e.real->vertex(CDT::cw(e.index));
    return star(j).s == m_i ? Vertex_handle() : star(j).s;
  }
  Vertex before(std::size_t j) const {
    const Entry& e = entry(j);
    if (e.star < 0) return e.real->vertex(CDT::ccw(e.index));
    return star(j).s == m_i ? star(j).t : Vertex_handle();
  }
  Constraint edge_after(std::size_t j) const { return edge(j, true); }
  Constraint edge_before(std::size_t j) const { return edge(j, false); }
  bool constrained_after(std::size_t j) const { return constrained(j, true); }
  bool same(const Constraint& a, const Constraint& b) const { return m_vi.same(a, b); }
  Point_2 clip_point(Vertex w, const Constraint& c) const {
    return m_vi.m_clip_point(m_i->point(), m_vi.point(w), m_vi.point(c.a), m_vi.point(c.b));
  }
  Point_2 midpoint(Vertex w) const { return CGAL::midpoint(m_i->point(), m_vi.point(w)); }
  const Point_2& generator() const { return m_i->point(); }

 private:
  struct Entry {
    Face_handle real;
    int index;  // of i in `real`
    int star;   // a face of the star, or -1
  };
  const Entry& entry(std::size_t j) const {
    const std::size_t k = m_entries.size();
    return m_entries[m_first + j < k ? m_first + j : m_first + j - k];
  }
  const Star_face& star(std::size_t j) const { return m_vi.m_star[std::size_t(entry(j).star)]; }
  bool constrained_before_entry(std::size_t j) const {  // before the rotation to m_first
    const Entry& e = m_entries[j];
    if (e.star < 0) return e.real->is_constrained(CDT::cw(e.index));
    const Star_face& s = m_vi.m_star[std::size_t(e.star)];
    return s.s == m_i ? s.rim_constrained : s.constrained_after;
  }
  // The edge of entry j at i after (true) or before (false) it, and whether it is constrained.
  bool constrained(std::size_t j, bool after_it) const {
    const Entry& e = entry(j);
    if (e.star < 0) return e.real->is_constrained(after_it ? CDT::ccw(e.index) : CDT::cw(e.index));
    const Star_face& s = star(j);
    const bool rim_side = (s.s == m_i) != after_it;  // (q, i, t): the rim edge is before
    return rim_side ? s.rim_constrained : (s.s == m_i ? s.constrained_before : s.constrained_after);
  }
  Constraint edge(std::size_t j, bool after_it) const {
    const Entry& e = entry(j);
    if (e.star < 0)
      return m_vi.real_constraint(Edge(e.real, after_it ? CDT::ccw(e.index) : CDT::cw(e.index)));
    const Star_face& s = star(j);
    const bool rim_side = (s.s == m_i) != after_it;
    if (rim_side) return m_vi.real_constraint(Edge(s.inner, s.index));
    return m_vi.half(m_i);
  }

  const Virtual_insertion& m_vi;
  Vertex_handle m_i;
  boost::container::small_vector<Entry, 16> m_entries;
  std::size_t m_first = 0;
  bool m_wedges = false;
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_VIRTUAL_INSERTION_H
