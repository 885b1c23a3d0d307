// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// natural_neighbor_coordinates_2(): Sibson and Laplace coordinates on the bounded Voronoi
// diagram, the constrained natural element method's shape functions; natural_neighbor_matrix_2():
// many queries at once, as a sparse matrix.
#ifndef CVT_2_NATURAL_NEIGHBOR_COORDINATES_2_H
#define CVT_2_NATURAL_NEIGHBOR_COORDINATES_2_H

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/internal/Virtual_insertion.h>
#include <CVT_2/internal/construct_cell.h>
#include <CVT_2/internal/lips.h>
#include <CVT_2/internal/parallel/run_chunks.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/parameters.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/tuple.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// Which natural-neighbour coordinates.
enum Natural_neighbor_method {
  SIBSON,  ///< \f$\phi_i = |C_q \cap C_i| / |C_q|\f$: the share of q's cell taken from i's
  LAPLACE  ///< \f$\lambda_i \propto s_i / h_i\f$: the bisector edge between q's and i's cells
           ///< over their distance (non-Sibsonian)
};

namespace internal {

// The coordinates of one query at a time, with the buffers they reuse.
template <class Diagram>
class Natural_neighbors {
 public:
  using Insertion = Virtual_insertion<Diagram>;
  using CDT = typename Diagram::Triangulation;
  using Point_2 = typename Diagram::Point_2;
  using FT = typename Diagram::FT;
  using Vertex_handle = typename Diagram::Vertex_handle;
  using Face_handle = typename Diagram::Face_handle;
  using Cell_vertex = typename Diagram::Cell_vertex;

  explicit Natural_neighbors(const Diagram& bvd) : m_insertion(bvd) {}

  // Queries on another diagram, the buffers kept.
  void attach(const Diagram& bvd) { m_insertion.attach(bvd); }

  // The unnormalized weights of q's natural neighbours into `out` (cleared), with a positive
  // weight each; false (and nothing) if q is outside the closed domain.
  // \throws Domain_error if q is inside but its weights are all 0 or not finite: its
  // neighbours' cells are too small for double precision at their coordinates (nodes a few
  // ulps apart), or their areas underflow or overflow (coordinates beyond 1e150 or 1e-150).
  bool compute(const Point_2& q, Natural_neighbor_method method, Face_handle& hint,
               std::vector<std::pair<Vertex_handle, FT>>& out) {
    out.clear();
    if (!is_valid_point(q))
      throw std::invalid_argument(invalid_point_message("query " + to_string(q)));
    switch (m_insertion.insert(q, hint)) {
      case Insertion::OUTSIDE:
        return false;
      case Insertion::ON_VERTEX:
        out.emplace_back(m_insertion.vertex(), FT(1));  // the Kronecker delta
        return true;
      default:
        break;
    }
    if (method == LAPLACE)
      laplace(out);
    else
      sibson(out);
    FT sum = 0;
    for (const auto& w : out) sum += w.second;
    if (!(sum > 0) || !CGAL::is_finite(sum))  // an empty row or NaNs would interpolate silently
      throw Domain_error("query " + to_string(q) +
                         ": its natural-neighbour weights vanish or are not finite in double "
                         "precision (its neighbours' cells are too small for their coordinates, "
                         "or their areas underflow or overflow)");
    return true;
  }

 private:
  struct Emission {
    Point_2 point;
    bool stable;  // made by the triangulation outside the zone alone: the same before and after
  };

  // Sibson: the area each rim vertex loses to q. Around a rim vertex i, q's star replaces a run
  // of the zone's faces by two, (q, i, t) and (q, s, i): i's cell loses the polygon of their
  // circumcenters and of the run's, when all of them see their circumcenters and no constraint
  // ends the run (the chain outside the run, clip points included, is the same before and
  // after). Elsewhere, near constraints, the whole chains of i before and after are compared.
  void sibson(std::vector<std::pair<Vertex_handle, FT>>& out) {
    const auto& star = m_insertion.star();
    const std::size_t n = star.size();
    m_slow.clear();
    // As many rim vertices as star faces, the last face ending where the first starts (a cycle,
    // or two chains across a split constraint): each rim vertex ends one face, no search.
    const bool distinct = m_insertion.rim().size() == n && star.back().t == star.front().s;
    for (std::size_t k = 0; k < n; ++k) {
      const auto& before = star[k];           // (q, s, i)
      const auto& after = star[(k + 1) % n];  // (q, i, t)
      const Vertex_handle i = before.t;
      FT lost = 0;
      const bool fast = i == after.s && run_area(before, after, distinct, lost);
      if (distinct) {
        out.emplace_back(i, lost);
        if (!fast) m_slow.push_back(i);
        continue;
      }
      auto it = std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == i; });
      if (it == out.end()) it = out.insert(out.end(), {i, FT(0)});
      it->second += lost;
      if (!fast && std::find(m_slow.begin(), m_slow.end(), i) == m_slow.end()) m_slow.push_back(i);
    }
    if (!distinct)
      for (const Vertex_handle i : m_insertion.rim())  // an end of a chain of the star alone
        if (std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == i; }) ==
            out.end())
          out.emplace_back(i, FT(0)), m_slow.push_back(i);
    // Near constraints, a node whose cell q's does not touch can still get a loss of rounding
    // from its two chains; it is a neighbour only if q's cell has an edge on their bisector.
    m_bisected.clear();
    if (!m_slow.empty())
      for_each_bisector_edge([&](Vertex_handle w, const FT&) { m_bisected.push_back(w); });
    for (const Vertex_handle i : m_slow) {
      const bool neighbor = std::find(m_bisected.begin(), m_bisected.end(), i) != m_bisected.end();
      std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == i; })->second =
          neighbor ? chain_difference(i) : FT(0);
    }
    out.erase(std::remove_if(out.begin(), out.end(), [](const auto& e) { return !(e.second > 0); }),
              out.end());
  }

  // The area the run of zone faces around i = before.t = after.s loses, if the fast case holds.
  // With each rim vertex once on the rim, i has no rim edges but those two: the run stays in
  // the zone.
  template <class Star_face>
  bool run_area(const Star_face& before, const Star_face& after, bool distinct, FT& lost) {
    if (before.blind || after.blind || before.constrained_after) return false;
    const Vertex_handle i = before.t;
    m_polygon.clear();
    m_polygon.push_back(after.center);
    Face_handle g = after.inner;  // holds the rim edge (i, t); the run turns counterclockwise
    Vertex_handle from = after.t;
    for (std::size_t steps = 0;; ++steps) {
      if (g->is_blinded() || steps > 64) return false;
      m_polygon.push_back(m_insertion.circumcenter(g));
      if (g == before.inner) break;
      const int u = g->index(from);
      if (g->is_constrained(u)) return false;
      from = g->vertex(3 - u - g->index(i));
      g = g->neighbor(u);
      if (!distinct && !m_insertion.in_conflict(g)) return false;
    }
    m_polygon.push_back(before.center);
    const Point_2& o = m_polygon[0];
    lost = 0;
    FT extent = 0;
    for (std::size_t k = 1; k + 1 < m_polygon.size(); ++k) {
      lost += triangle(o, m_polygon[k], m_polygon[k + 1]);
      extent = (std::max)(
          extent, CGAL::abs(m_polygon[k].x() - o.x()) + CGAL::abs(m_polygon[k].y() - o.y()));
    }
    // A loss at the level of rounding: if q, s, i, t lie on a circle, the two circumcenters are
    // one, q's cell has no edge on the bisector of q and i, and i loses nothing, exactly.
    if (CGAL::abs(lost) <= 0x1.0p-40 * extent * extent &&
        CGAL::side_of_oriented_circle(m_insertion.query(), before.s->point(), i->point(),
                                      after.t->point()) == CGAL::ON_ORIENTED_BOUNDARY)
      lost = 0;
    return true;
  }

  // The area i loses, from its cell's chains before and after.
  FT chain_difference(Vertex_handle i) {
    m_before.clear();
    m_after.clear();
    for (const bool after : {false, true}) {
      const typename Insertion::Neighbor_fan fan(m_insertion, i, after);
      std::vector<Emission>& chain = after ? m_after : m_before;
      fan_chain(fan, [&](const Point_2& p, auto type, std::size_t j, const auto&, auto) {
        chain.push_back({p, type == Cell_vertex::GENERATOR ||
                                (type == Cell_vertex::CIRCUMCENTER && fan.stable(j))});
      });
    }
    return difference(i->point(), m_before, m_after);
  }

  static FT triangle(const Point_2& x, const Point_2& u, const Point_2& v) {
    return ((u.x() - x.x()) * (v.y() - x.y()) - (u.y() - x.y()) * (v.x() - x.x())) / 2;
  }

  // Area(a) - area(b) of two cells of generator x given as cyclic chains that agree but for one
  // run: the chains are turned to a point both make alike, their common ends skipped, and the
  // fan triangles from x summed over the two runs between the last common point before and the
  // first after. Only the part that changed is summed, so a small loss is not lost in the
  // cancellation of two large areas.
  static FT difference(const Point_2& x, const std::vector<Emission>& a,
                       const std::vector<Emission>& b) {
    const std::size_t n = a.size(), m = b.size();
    const auto area = [&x](const std::vector<Emission>& c) {
      FT s = 0;
      for (std::size_t k = 0; k < c.size(); ++k)
        s += triangle(x, c[k].point, c[(k + 1) % c.size()].point);
      return s;
    };
    std::size_t ia = n, ib = m;
    for (std::size_t k = 0; k < n && ia == n; ++k) {
      if (!a[k].stable) continue;
      for (std::size_t l = 0; l < m; ++l)
        if (b[l].stable && b[l].point == a[k].point) {
          ia = k, ib = l;
          break;
        }
    }
    if (ia == n) return area(a) - area(b);
    const auto A = [&](std::size_t k) -> const Point_2& { return a[(ia + k) % n].point; };
    const auto B = [&](std::size_t k) -> const Point_2& { return b[(ib + k) % m].point; };
    std::size_t p = 1;
    while (p < n && p < m && A(p) == B(p)) ++p;
    if (p == n && p == m) return 0;
    std::size_t s = 0;
    while (s + p < n && s + p < m && A(n - 1 - s) == B(m - 1 - s)) ++s;
    FT lost = 0;
    for (std::size_t k = p - 1; k < n - s; ++k) lost += triangle(x, A(k), A(k + 1));
    for (std::size_t k = p - 1; k < m - s; ++k) lost -= triangle(x, B(k), B(k + 1));
    return lost;
  }

  // Laplace: each bisector edge of q's cell, by the neighbour across it: its length over the
  // neighbour's distance.
  void laplace(std::vector<std::pair<Vertex_handle, FT>>& out) {
    for_each_bisector_edge([&](Vertex_handle w, const FT& length) {
      const FT h = CGAL::sqrt(CGAL::squared_distance(m_insertion.query(), w->point()));
      auto it = std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == w; });
      if (it == out.end())
        out.emplace_back(w, length / h);
      else
        it->second += length / h;
    });
  }

  // visit(w, length) for each edge of q's cell on the bisector of q and a node w, in turn; the
  // edges along constraints are not bisectors.
  template <class Visit>
  void for_each_bisector_edge(Visit visit) {
    using Fan = typename Insertion::Query_fan;
    using Constraint = typename Fan::Constraint;
    m_chain.clear();
    const Fan fan(m_insertion);
    fan_chain(fan,
              [&](const Point_2& p, auto type, std::size_t, const Constraint& c, Vertex_handle w) {
                m_chain.push_back({p, int(type), c, w});
              });
    const auto on = [&](const Point_of_cell& x, const Constraint& c) {
      if (x.type == Cell_vertex::GENERATOR)
        return c.a == Vertex_handle() || c.b == Vertex_handle();  // q is an end of c
      return x.type == Cell_vertex::CLIP_POINT && m_insertion.same(x.constraint, c);
    };
    for (std::size_t k = 0; k < m_chain.size(); ++k) {
      const Point_of_cell& x = m_chain[k];
      const Point_of_cell& y = m_chain[(k + 1) % m_chain.size()];
      if (x.point == y.point) continue;
      if ((x.type == Cell_vertex::CLIP_POINT && on(y, x.constraint)) ||
          (y.type == Cell_vertex::CLIP_POINT && on(x, y.constraint)))
        continue;  // along a constraint
      visit(x.type == Cell_vertex::GENERATOR ? y.w : x.w,
            CGAL::sqrt(CGAL::squared_distance(x.point, y.point)));
    }
  }

  struct Point_of_cell {
    Point_2 point;
    int type;
    typename Insertion::Constraint constraint;
    Vertex_handle w;
  };

  Insertion m_insertion;
  std::vector<Emission> m_before, m_after;
  std::vector<Vertex_handle> m_slow, m_bisected;
  std::vector<Point_2> m_polygon;
  std::vector<Point_of_cell> m_chain;
};

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// The natural-neighbour coordinates of `q` on the bounded Voronoi diagram `bvd`: those of the
/// constrained natural element method (Yvonnet, Ryckelynck, Lorong, Chinesta 2004), in which a
/// node that a constraint hides from q gets no weight. Insert q virtually: its bounded Voronoi
/// cell \f$C_q\f$ takes area from the cells of its natural neighbours.
/// - Sibson: the weight of node i is the area \f$|C_q \cap C_i|\f$ that i's cell loses.
/// - Laplace: \f$s_i / h_i\f$, the length of the bisector edge between \f$C_q\f$ and i's cell
///   (edges on constraints do not count) over \f$|q - x_i|\f$.
///
/// Nothing is inserted: the conflict zone of q in the constrained triangulation (it never
/// crosses a constraint) and the blind tags of q's virtual star, found by the exact predicates
/// of the diagram's traits, give both cells. The output has the shape of CGAL's
/// `natural_neighbor_coordinates_2()`, so that CGAL's interpolation functions
/// (`CGAL::linear_interpolation()`, `CGAL::sibson_c1_interpolation()`, ...) take it as it is:
/// `std::pair<Vertex_handle, FT>` for each node with a positive weight (not normalized) are
/// written to `out`, and the result holds the output iterator, the normalizer (the weights'
/// sum) and whether q lies in the closed domain (`false`: nothing written). At a node, the
/// node alone, weight 1.
///
/// \tparam Diagram a `Bounded_voronoi_diagram_2`, up to date with its triangulation, whose
///         traits have `construct_dual_segment_2_object()` (`Bvd_traits_2` has).
/// \param np optional named parameters:
///   - `natural_neighbor_method(m)`: `SIBSON` (the default) or `LAPLACE`.
///   - `hint(f)`: a face near q, where the point location starts (the previous query's, say);
///     it changes no bit of the result.
/// \throws std::invalid_argument if q is not finite or exceeds 1e300 in magnitude;
///         `Domain_error` (one) if q is inside but its weights vanish or are not finite in double
///         precision: nodes a few ulps apart, or coordinates whose squares underflow or overflow.
template <class Diagram, class OutputIterator, class NP = No_named_parameters>
CGAL::Triple<OutputIterator, typename Diagram::FT, bool> natural_neighbor_coordinates_2(
    const Diagram& bvd, const typename Diagram::Point_2& q, OutputIterator out,
    const NP& np = parameters::default_values()) {
  using namespace internal_np;
  using FT = typename Diagram::FT;
  const Natural_neighbor_method method =
      choose_parameter(get_parameter(np, natural_neighbor_method_t()), SIBSON);
  typename Diagram::Face_handle hint =
      choose_parameter(get_parameter(np, hint_t()), typename Diagram::Face_handle());
  // The buffers of the last call on this thread, so that a query allocates nothing.
  thread_local internal::Natural_neighbors<Diagram> nn(bvd);
  thread_local std::vector<std::pair<typename Diagram::Vertex_handle, FT>> weights;
  nn.attach(bvd);
  const bool inside = nn.compute(q, method, hint, weights);
  FT norm = 0;
  for (const auto& w : weights) {
    *out++ = w;
    norm += w.second;
  }
  return CGAL::make_triple(out, norm, inside);
}

/// \ingroup PkgCvt2Ref
/// The lip of node `v` that `q` sees it from, numbered as `natural_neighbor_matrix_2()` numbers
/// the lips (`lips(true)`): the wedges of the domain between the constraints of `v`,
/// counterclockwise; 0 for a free node. A value on each lip of a node along a crack is then the
/// field's limit from that side: its value at `v` seen from a point `q` just off the crack.
/// Returns -1 if no wedge of the domain around `v` holds the direction to `q`.
template <class Diagram>
int node_lip_2(const Diagram& bvd, typename Diagram::Vertex_handle v,
               const typename Diagram::Point_2& q) {
  return internal::lip_toward(bvd.triangulation(), v, q);
}

/// \ingroup PkgCvt2Ref
/// The natural-neighbour coordinates of many queries as a sparse matrix in compressed rows:
/// row k holds the normalized coordinates of `queries[k]` (summing to 1; empty for a query
/// outside the closed domain), in `columns` (nodes, numbered by `nodes`, then their lips if
/// asked for) and `values`.
template <class Vertex_handle, class FT>
struct Natural_neighbor_matrix_2 {
  std::vector<Vertex_handle> nodes;  ///< column j is node `nodes[j]`: the diagram's generators,
                                     ///< in the triangulation's order of vertices
  /// With `lips(true)`: column `nodes.size() + k` is a lip of node `lip_nodes[k]` (a column),
  /// the lips of a node in a row, counterclockwise around it
  std::vector<std::size_t> lip_nodes;
  std::vector<std::size_t> row_offsets{0};  ///< row k: `[row_offsets[k], row_offsets[k + 1])`
  std::vector<std::size_t> columns;         ///< by row, increasing within a row
  std::vector<FT> values;                   ///< likewise
  std::vector<unsigned char> inside;        ///< whether each query lies in the closed domain
};

/// \ingroup PkgCvt2Ref
/// `natural_neighbor_coordinates_2()` for every point of `queries`, on all cores, as a sparse
/// matrix (`Natural_neighbor_matrix_2`): the shape functions of the constrained natural element
/// method at those points. Queries are taken in chunks in their order, each located from the
/// one before it (spatially sorted queries locate fastest); a query's row is the same, bit for
/// bit, whatever the number of threads and the queries around it.
///
/// With `lips(true)`, a node with two lips or more (a vertex along a crack, or where a crack
/// meets another constraint: the wedges of the domain between its constraints) has a column
/// for each, after the nodes' columns, and its own column stays empty: a query's weight goes to
/// the lip it sees the node from. A field that jumps across a crack then has a value on each
/// lip of each node on it (the lip duplication of the constrained natural element method). A
/// query on a constraint through a node counts on one of the lips beside it; one at the node,
/// on its lip 0.
/// \param np optional named parameters: `natural_neighbor_method(m)` (default `SIBSON`),
///        `number_of_threads(n)` (default 0, one per core), `lips(b)` (default false).
/// \throws std::invalid_argument for a query that is not finite, naming it, and `Domain_error`
///         for a query inside whose weights vanish or are not finite in double precision.
template <class Diagram, class PointRange, class NP = No_named_parameters>
Natural_neighbor_matrix_2<typename Diagram::Vertex_handle, typename Diagram::FT>
natural_neighbor_matrix_2(const Diagram& bvd, const PointRange& queries,
                          const NP& np = parameters::default_values()) {
  using namespace internal_np;
  using Vertex_handle = typename Diagram::Vertex_handle;
  using FT = typename Diagram::FT;
  using Point_2 = typename Diagram::Point_2;
  const Natural_neighbor_method method =
      choose_parameter(get_parameter(np, natural_neighbor_method_t()), SIBSON);
  const auto threads = choose_parameter(get_parameter(np, number_of_threads_t()), 0u);
  const bool with_lips = choose_parameter(get_parameter(np, lips_t()), false);
  Natural_neighbor_matrix_2<Vertex_handle, FT> m;
  const auto& cdt = bvd.triangulation();
  // Columns in a hash map: the diagram is not ours to write (vertex ids may hold a mesh's
  // numbers, or the user's). CGAL's, keyed by the handles' addresses, keeps its items in one
  // table (a lookup is one read of memory, on any number of threads; std::unordered_map's are
  // nodes of their own, one allocation an insertion).
  CGAL::Unique_hash_map<Vertex_handle, std::size_t> column(std::size_t(-1),
                                                           cdt.number_of_vertices());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (bvd.has_cell(v)) {
      column[v] = m.nodes.size();
      m.nodes.push_back(v);
    }
  // the first lip column of each node with two lips or more
  CGAL::Unique_hash_map<Vertex_handle, std::size_t> lip_column(std::size_t(-1));
  if (with_lips)
    for (std::size_t j = 0; j < m.nodes.size(); ++j) {
      const Vertex_handle v = m.nodes[j];
      const int lips = cdt.are_there_incident_constraints(v) ? internal::number_of_lips(cdt, v) : 1;
      if (lips < 2) continue;
      lip_column[v] = m.nodes.size() + m.lip_nodes.size();
      m.lip_nodes.insert(m.lip_nodes.end(), std::size_t(lips), j);
    }
  const auto& columns = column;  // const from here: lookups only, thread-safe
  const auto& lip_columns = lip_column;
  const std::vector<Point_2> q(std::begin(queries), std::end(queries));
  constexpr std::size_t chunk = 1024;
  const std::size_t chunks = (q.size() + chunk - 1) / chunk;
  struct alignas(internal::cache_line) Rows {
    std::vector<std::size_t> ends, columns;  // ends: of each row, from the chunk's start
    std::vector<FT> values;
  };
  std::vector<Rows> rows(chunks);
  m.inside.resize(q.size());
  internal::run_chunks(chunks, static_cast<unsigned>(threads), [&](std::size_t c) {
    internal::Natural_neighbors<Diagram> nn(bvd);
    std::vector<std::pair<Vertex_handle, FT>> w;
    std::vector<std::pair<std::size_t, FT>> row;
    typename Diagram::Face_handle hint;
    Rows& out = rows[c];
    for (std::size_t k = c * chunk; k < std::min(q.size(), (c + 1) * chunk); ++k) {
      m.inside[k] = nn.compute(q[k], method, hint, w) ? 1 : 0;
      FT norm = 0;
      for (const auto& e : w) norm += e.second;
      row.clear();
      for (const auto& e : w) {
        std::size_t j = columns[e.first];
        CGAL_assertion(j != std::size_t(-1));  // a neighbour is a vertex of a domain face
        if (with_lips && lip_columns.is_defined(e.first))
          j = lip_columns[e.first] +
              std::size_t(std::max(0, internal::lip_toward(cdt, e.first, q[k])));
        row.emplace_back(j, e.second / norm);
      }
      std::sort(row.begin(), row.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (const auto& [j, value] : row) out.columns.push_back(j), out.values.push_back(value);
      out.ends.push_back(out.columns.size());
    }
  });
  // The chunks' rows in place, each at the sum of the sizes before it.
  std::vector<std::size_t> start(chunks + 1, 0);
  for (std::size_t c = 0; c < chunks; ++c) start[c + 1] = start[c] + rows[c].columns.size();
  m.row_offsets.resize(q.size() + 1);
  m.columns.resize(start.back());
  m.values.resize(start.back());
  internal::run_chunks(chunks, static_cast<unsigned>(threads), [&](std::size_t c) {
    Rows& r = rows[c];
    for (std::size_t k = 0; k < r.ends.size(); ++k)
      m.row_offsets[c * chunk + k + 1] = start[c] + r.ends[k];
    std::copy(r.columns.begin(), r.columns.end(), m.columns.begin() + std::ptrdiff_t(start[c]));
    std::copy(r.values.begin(), r.values.end(), m.values.begin() + std::ptrdiff_t(start[c]));
    r = Rows();
  });
  return m;
}

}  // namespace CVT_2

#endif  // CVT_2_NATURAL_NEIGHBOR_COORDINATES_2_H
