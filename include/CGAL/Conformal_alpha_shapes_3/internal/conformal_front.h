// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CONFORMAL_FRONT_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CONFORMAL_FRONT_H

// The advancing front that grows the surface (the manual, "The Advancing
// Front"), the soup of triangle_soup.h, grown on the shape's own
// triangulation: no copy of it, no 2D data
// structure, the front's state in flat arrays indexed by vertex rank and
// cell index. It follows the rules of CGAL's
// Advancing_front_surface_reconstruction (CGAL 5.5) with the priority
// `Conformal_priority` (cgal_front.h), so that it selects the same facets:
//
// - a part is seeded at the smallest facet (by priority) whose three
//   vertices are off the surface, the first one in the order of the finite
//   facets when several tie (`Front_seeding` stops the seeding);
// - each border edge holds its best candidate facet around it (the smallest
//   priority among the facets that would not fold the surface back, a
//   "sliver" test at cos = -0.86) and a criterion: -(1 + 1/value) when the
//   candidate turns from the edge's facet by less than beta = 0.52, else
//   -cos(turn) when its value is at most K times the edge's facet's value,
//   else "stand by" (3), or "not valid" (5) when there is no candidate or it
//   has an angle along the edge wider than acos(-0.86);
// - border edges are taken smallest criterion first; the candidate is
//   validated as CGAL does (an ear closing on one or two border edges, a new
//   vertex, or a vertex already on the border joined when one of the two
//   ears it makes is valid and the border orientations agree), refused
//   connections are queued on the vertex (an incidence request) until its
//   border changes;
// - when only stand-by edges are left every border edge is re-evaluated, K
//   starting at 1.1 and growing by at least 0.1 (K is 5 for the first
//   seed's edges, and what the last part left it at for the next seeds, as
//   in CGAL);
// - CGAL's postprocessing (removing vertices it could not attach and
//   growing again) never removes a vertex in CGAL 5.5: its test compares
//   with a size that is never set (`_size_before_postprocessing` is 0). Its
//   only effect is to drop every pending incidence request once the front
//   has more facets than the triangulation has vertices; so it is here. The
//   triangulation is therefore never modified, which is what lets the front
//   run on the shape itself.
//
// Where CGAL orders by memory address, the order here is by an index:
// - the border edges of equal criterion: CGAL orders them by the address
//   of the vertex's border record holding the edge (two per vertex,
//   allocated at the start in the order of the vertices); here by
//   (rank of the vertex in the triangulation's order, which of its two
//   records). Same as CGAL where the allocator hands out increasing
//   addresses;
// - the finite facets: CGAL visits a facet from its cell of smaller
//   address, here from its cell of smaller index (the shape's cell order,
//   which is the order of the copy CGAL runs on). This decides the side, so
//   the orientation, of each part's seed.
// - the faces of the surface: CGAL creates them in the order of the finite
//   facets (so by address as above) and turns each connected set of faces
//   (through their borders too) to agree with its first face. Here the
//   faces are in the cell index order: the same triangles and neighbors.
//   A facet's value is the same from either of its cells (its radius is
//   computed in the order of its vertices' indices), so the values are
//   the same bits as CGAL's.
// The criterion ties are frequent among stand-by and not-valid edges,
// whose order does not matter (they are re-evaluated all at once), and
// rare among valid ones (two border edges sharing their candidate facet).
//
// The cost is CGAL's, but for the seeding (CGAL scans every facet for each
// part: here the first scan runs in chunks side by side, and the facets
// left all exterior after the first part are listed so and sorted once),
// the copies (no copy of the triangulation, no 2D structure), the surface's faces
// (sorted from the facets taken, not found by a walk over all facets) and
// the re-evaluations of every border edge each time a part runs out of
// valid candidates, where CGAL spends most of its time when the front
// leaves many holes, nearly all of them re-evaluating edges that stay "not
// valid" (the manual, "Performance", has the figures). Here an edge keeps
// its search for its best facet, that holds while that facet may still be
// taken, and only classifies it again for the new K
// (`re_compute_value()`); the edges left "not valid" sleep out of the
// border's order until something they depend on changes
// (`put_to_sleep()`); and the border's ordered set is a heap (`Key_set`).

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/front_priority.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/triangle_soup.h>
#include <CGAL/Conformal_alpha_shapes_3/interruption.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

template <class Cas>
class Conformal_front
{
public:
  typedef typename Cas::Geom_traits Gt;
  typedef typename Cas::Cell_handle Cell_handle;
  typedef typename Cas::Vertex_handle Vertex_handle;
  typedef typename Gt::Point_3 Point;
  typedef typename Gt::Vector_3 Vector;
  typedef std::uint32_t Id;
  static constexpr Id none = Id(-1);

private:
  // A facet of cell `c` (opposite to its vertex `i`) seen from its edge
  // (c->vertex(i1), c->vertex(i2)): CGAL's Edge_incident_facet.
  struct Edge_facet
  {
    Cell_handle c{};
    std::int8_t i1 = 0, i2 = 0, i = 0;  // 16 bytes: the border's records hold 4
    Edge_facet() = default;
    Edge_facet(Cell_handle c, int i1, int i2, int i) : c(c), i1(std::int8_t(i1)), i2(std::int8_t(i2)), i(std::int8_t(i)) {}
    bool operator==(const Edge_facet& o) const { return c == o.c && i1 == o.i1 && i2 == o.i2 && i == o.i; }
    bool operator!=(const Edge_facet& o) const { return !(*this == o); }
  };
  // What a border edge's criterion is made of but K (see
  // `compute_value()`): the smallest priority among the facets around the
  // edge that may be taken (infinity: none) and the cosine of its turn, the
  // third vertex of that facet (none: no facet), whether the criterion is
  // "not valid" for every K, and the priority of the edge's own facet when
  // the criterion compares with it.
  struct Search
  {
    double best = 0, cos = 0, own = 0;
    Id best_vertex = none;
    bool not_valid = false;
  };
  // A border edge's criterion, its facet on the surface and its candidate
  // facet: CGAL's Radius_edge_type; with its search, that classifies the
  // edge again for another K while the search still holds.
  struct Candidate
  {
    double value = 0;
    Edge_facet facet, candidate;
    Search search;
    bool operator!=(const Candidate& o) const
    {
      return value != o.value || facet != o.facet || candidate != o.candidate;
    }
  };
  // CGAL's Border_elt: a candidate and the border's number.
  struct Border_elt
  {
    Candidate candidate;
    int border = 0;
  };
  // One of a vertex's two border records (CGAL's Next_border_elt): the
  // edge's other end (`none`: the record is free; its content stays).
  struct Record
  {
    Id to = none;
    Border_elt elt;
  };
  struct Request
  {
    double value;
    Id from, to;
    Id next;
  };
  struct Interior
  {
    Id to;
    Id next;
  };
  typedef std::pair<double, Id> Key;  // criterion, record
  // CGAL's ordered set of the border's keys, as a heap: an erased key stays
  // in the heap until it comes up, and is dropped then (the border holds
  // hundreds of thousands of keys at a million points, and a tree's
  // insertion misses the cache at each level). Which keys are in the set is
  // kept by record: a record mostly has one key at a time, its value; the
  // others are in a small set.
  class Key_set
  {
  public:
    void reset(std::size_t number_of_records)
    {
      heap.clear();
      value.assign(number_of_records, no_key);
      more.clear();
      size = 0;
    }
    bool empty() const { return size == 0; }
    void insert(const Key& k)
    {
      double& v = value[k.second];
      if(std::isnan(v))
        v = k.first;
      else if(v == k.first || !more.insert(Record_key(k.second, k.first)).second)
        return;
      ++size;
      heap.push_back(k);
      std::push_heap(heap.begin(), heap.end(), std::greater<Key>());
    }
    void erase(const Key& k)
    {
      double& v = value[k.second];
      if(std::isnan(v))
        return;
      if(v == k.first)
      {
        // another key of the record, if any, takes its place
        const auto other = more.lower_bound(Record_key(k.second, -std::numeric_limits<double>::infinity()));
        if(other != more.end() && other->first == k.second)
        {
          v = other->second;
          more.erase(other);
        }
        else
          v = no_key;
      }
      else if(more.erase(Record_key(k.second, k.first)) == 0)
        return;
      --size;
    }
    // the smallest key (the set is not empty)
    Key front()
    {
      drop_erased();
      return heap.front();
    }
    void pop_front()
    {
      drop_erased();
      erase(heap.front());
      pop_heap();
    }
    // empties the set, in the time of its heap
    void clear()
    {
      for(const Key& k : heap)
        value[k.second] = no_key;
      heap.clear();
      more.clear();
      size = 0;
    }

  private:
    typedef std::pair<Id, double> Record_key;
    static constexpr double no_key = std::numeric_limits<double>::quiet_NaN();  // never a criterion
    std::vector<Key> heap;     // smallest first; each key in the set at least once
    std::vector<double> value; // by record
    std::set<Record_key> more;
    std::size_t size = 0;

    bool contains(const Key& k) const
    {
      const double v = value[k.second];
      return v == k.first || (!more.empty() && more.count(Record_key(k.second, k.first)) != 0);
    }
    void pop_heap()
    {
      std::pop_heap(heap.begin(), heap.end(), std::greater<Key>());
      heap.pop_back();
    }
    void drop_erased()
    {
      while(!contains(heap.front()))
        pop_heap();
    }
  };
  enum Validation_case { NOT_VALID, NOT_VALID_CONNECTING_CASE, FINAL_CASE, EAR_CASE, EXTERIOR_CASE, CONNECTING_CASE };

  const Cas& cas;
  const Gt& gt;
  const double infinity = std::numeric_limits<double>::infinity();
  const double COS_ALPHA_SLIVER = -0.86, DELTA = .86, eps = 1e-7;
  const double STANDBY_CANDIDATE = 3, STANDBY_CANDIDATE_BIS = 4, NOT_VALID_CANDIDATE = 5;
  const double K_init = 1.1, K_step = .1;
  double COS_BETA;
  double K, min_K;

  std::vector<Id> rank_of_index;  // vertex index -> rank in the triangulation's order
  Id infinite_rank = none;
  std::vector<int> mark;           // by rank: -1 exterior, 0 interior, > 0 on the border
  std::vector<Id> first_record, second_record;  // by rank; none: no border (CGAL's null)
  std::vector<Record> records;     // 2 per vertex, 2 r and 2 r + 1
  std::vector<Id> interior_head;   // by rank, into `interiors`
  std::vector<Interior> interiors;
  std::vector<Id> request_head, request_tail;  // by rank, into `requests`
  std::vector<Request> requests;
  Id free_request = none;
  std::vector<std::pair<Cell_handle, int> > selected;  // the facets taken, from the side taken
  Key_set ordered_border;
  // The border edges that re-evaluating would leave as they are ("asleep"):
  // keys (NOT_VALID_CANDIDATE, record) of the border kept out of
  // `ordered_border`, each watching the vertices it depends on (see
  // `put_to_sleep()`).
  struct Watch
  {
    Id record;
    Id next;
  };
  std::vector<char> asleep;                  // by record
  std::size_t number_asleep = 0;
  std::vector<Id> watch_head;                // by rank, into `watches`
  std::vector<Watch> watches;
  Id free_watch = none;
  const Key* pass_key = nullptr;             // the key re_compute_values() is at
  std::vector<Key>* pass_output = nullptr;   // and its re-evaluated keys
  int number_of_components = 0;
  int number_of_selected = 0;

  Front_seeding seeding;
  Interruption_point interruption;
  std::size_t calls = 0;
  std::size_t anomalies = 0;  // states where CGAL would print a warning or crash

  // the all-exterior facets, sorted by priority then finite-facet order, of
  // the seeding after the first one (built at the second seeding)
  std::vector<std::pair<double, std::uint64_t> > seeds;
  std::size_t next_seed = 0;
  bool seeds_ready = false;

public:
  explicit Conformal_front(const Cas& shape)
    : cas(shape), gt(shape.geom_traits()), seeding(shape.number_of_vertices())
  {}

  int number_of_connected_components() const { return number_of_components; }
  int number_of_facets() const { return number_of_selected; }
  std::size_t number_of_anomalies() const { return anomalies; }

  Id rank(Vertex_handle v) const
  {
    return v == cas.infinite_vertex() ? infinite_rank : rank_of_index[v->vertex_index()];
  }
  Id rank(Cell_handle c, int k) const { return rank(c->vertex(k)); }

private:
  bool is_on_border(Id v) const { return mark[v] > 0; }
  bool not_interior(Id v) const { return mark[v] != 0; }
  bool is_exterior(Id v) const { return mark[v] < 0; }
  void inc_mark(Id v) { mark[v] = mark[v] == -1 ? 1 : mark[v] + 1; }

  // The priority (Conformal_priority on the shape's cells).
  double priority(Cell_handle c, int i)
  {
    if(++calls % 1024 == 0)
      interruption.throw_if_stopped();
    const bool seed = is_exterior(rank(c, (i + 1) & 3)) && is_exterior(rank(c, (i + 2) & 3))
                      && is_exterior(rank(c, (i + 3) & 3));
    if(seed && !seeding.may_seed(*this))
      return infinity;
    return facet_priority(c, i);
  }
  double facet_priority(Cell_handle c, int i) const
  {
    return tie_broken_value(double(cas.conformal_alpha(c, i)), c->vertex((i + 1) & 3)->vertex_index(),
                            c->vertex((i + 2) & 3)->vertex_index(), c->vertex((i + 3) & 3)->vertex_index());
  }

  // --- border records ---------------------------------------------------
  Id border_elt(Id v1, Id v2) const
  {
    const Id f = first_record[v1];
    if(f == none)
      return none;
    if(records[f].to == v2)
      return f;
    if(records[second_record[v1]].to == v2)
      return second_record[v1];
    return none;
  }
  void set_next_border_elt(Id v1, Id v2, const Border_elt& e)
  {
    touch(v1);
    if(first_record[v1] == none)
    {
      ++anomalies;  // CGAL would write through a null pointer
      return;
    }
    Record& f = records[first_record[v1]];
    if(f.to == none)
      f = Record{v2, e};
    else
    {
      if(records[second_record[v1]].to != none)
        ++anomalies;  // CGAL: "probleme de MAJ du bord"
      records[second_record[v1]] = Record{v2, e};
    }
  }
  Id set_border_elt(Id v1, Id v2, const Border_elt& e)
  {
    set_next_border_elt(v1, v2, e);
    return border_elt(v1, v2);
  }
  Id set_again_border_elt(Id v1, Id v2, const Border_elt& e)
  {
    const Id r = border_elt(v1, v2);
    if(r == none)
    {
      ++anomalies;  // CGAL would write through a null pointer
      return none;
    }
    wake(r);
    records[r].elt = e;
    return r;
  }
  void remove_border_edge(Id w, Id v)
  {
    touch(w);
    if(first_record[w] == none)
      return;
    if(records[second_record[w]].to == v)
    {
      records[second_record[w]].to = none;
      set_interior_edge(w, v);
      return;
    }
    if(records[first_record[w]].to == v)
    {
      if(records[second_record[w]].to != none)
      {
        std::swap(first_record[w], second_record[w]);
        records[second_record[w]].to = none;
      }
      else
        records[first_record[w]].to = none;
      set_interior_edge(w, v);
    }
  }
  // CGAL's is_border_elt(key, result): the edge in either direction, the
  // key turned to the direction found
  bool is_border_elt(std::pair<Id, Id>& key, Border_elt& result) const
  {
    Id r = border_elt(key.first, key.second);
    if(r != none)
    {
      result = records[r].elt;
      return true;
    }
    r = border_elt(key.second, key.first);
    if(r != none)
    {
      result = records[r].elt;
      std::swap(key.first, key.second);
      return true;
    }
    return false;
  }
  bool is_ordered_border_elt(const std::pair<Id, Id>& key, Border_elt& result) const
  {
    const Id r = border_elt(key.first, key.second);
    if(r == none)
      return false;
    result = records[r].elt;
    return true;
  }
  void insert(double value, Id record)
  {
    if(record != none)
    {
      wake(record);
      ordered_border.insert(Key(value, record));
    }
  }

  // --- the border edges asleep ----------------------------------------------
  // A key (NOT_VALID_CANDIDATE, r) that re_compute_values() leaves with a
  // "not valid" search in record r, written there from r's own edge, goes to
  // sleep. Re-evaluated, it would find record r again from that edge, the
  // same search (see `re_compute_value()`), a criterion NOT_VALID_CANDIDATE
  // whatever K, and write record r as it is: the same key, nothing changed.
  // That holds until record r is written, or the border records of its two
  // vertices change (what finds r from the edge), or the vertex of its
  // search's best facet becomes interior or gets an interior edge: each of
  // these `touch()`es one of the three vertices, which wakes the key up.
  bool border_is_empty() const { return ordered_border.empty() && number_asleep == 0; }
  // the smallest criterion of a nonempty border: asleep, they are the largest
  double smallest_criterion()
  {
    return ordered_border.empty() ? NOT_VALID_CANDIDATE : ordered_border.front().first;
  }
  void put_to_sleep(Id r)
  {
    asleep[r] = 1;
    ++number_asleep;
    watch(r / 2, r);
    watch(records[r].to, r);
    if(records[r].elt.candidate.search.best_vertex != none)
      watch(records[r].elt.candidate.search.best_vertex, r);
  }
  void watch(Id v, Id r)
  {
    Id k;
    if(free_watch != none)
    {
      k = free_watch;
      free_watch = watches[k].next;
    }
    else
    {
      k = Id(watches.size());
      watches.push_back(Watch());
    }
    watches[k] = Watch{r, watch_head[v]};
    watch_head[v] = k;
  }
  // Back to `ordered_border`; during re_compute_values() (only when a stale
  // key writes the record), where that pass would have it: still ahead of
  // it, or already passed, as it was.
  void wake(Id r)
  {
    if(!asleep[r])
      return;
    asleep[r] = 0;
    --number_asleep;
    const Key key(NOT_VALID_CANDIDATE, r);
    if(pass_key != nullptr && key < *pass_key)
      pass_output->push_back(key);
    else
      ordered_border.insert(key);
  }
  // wakes the edges that depend on `v`
  void touch(Id v)
  {
    Id k = watch_head[v];
    if(k == none)
      return;
    for(;; k = watches[k].next)
    {
      wake(watches[k].record);
      if(watches[k].next == none)
        break;
    }
    watches[k].next = free_watch;
    free_watch = watch_head[v];
    watch_head[v] = none;
  }

  // --- interior edges and incidence requests ---------------------------
  void set_interior_edge(Id w, Id v)
  {
    touch(w);
    touch(v);
    interiors.push_back(Interior{v, interior_head[w]});
    interior_head[w] = Id(interiors.size() - 1);
  }
  bool is_interior_edge(Id w, Id v) const
  {
    for(Id k = interior_head[w]; k != none; k = interiors[k].next)
      if(interiors[k].to == v)
        return true;
    return false;
  }
  bool is_interior_edge(const std::pair<Id, Id>& e) const
  {
    return is_interior_edge(e.first, e.second) || is_interior_edge(e.second, e.first);
  }
  void set_incidence_request(Id w, double value, const std::pair<Id, Id>& e)
  {
    Id k;
    if(free_request != none)
    {
      k = free_request;
      free_request = requests[k].next;
    }
    else
    {
      k = Id(requests.size());
      requests.push_back(Request());
    }
    requests[k] = Request{value, e.first, e.second, none};
    if(request_head[w] == none)
      request_head[w] = k;
    else
      requests[request_tail[w]].next = k;
    request_tail[w] = k;
  }
  void erase_incidence_request(Id w)
  {
    if(request_head[w] == none)
      return;
    requests[request_tail[w]].next = free_request;
    free_request = request_head[w];
    request_head[w] = request_tail[w] = none;
  }
  void dequeue_incidence_request(Id v)
  {
    for(Id k = request_head[v]; k != none; k = requests[k].next)
    {
      const Id r = border_elt(requests[k].from, requests[k].to);
      insert(requests[k].value, r);
    }
    erase_incidence_request(v);
  }
  void dec_mark(Id w)
  {
    --mark[w];
    if(mark[w] == 0)
    {
      touch(w);
      first_record[w] = second_record[w] = none;
      erase_incidence_request(w);
    }
  }
  void select_facet(Cell_handle c, int i)
  {
    selected.emplace_back(c, i);
    ++number_of_selected;
  }

  // --- geometry and candidates --------------------------------------------
  Edge_facet next(const Edge_facet& e) const
  {
    const int i3 = 6 - e.i - e.i1 - e.i2;
    const Cell_handle n = e.c->neighbor(e.i);
    return Edge_facet{n, n->index(e.c->vertex(e.i1)), n->index(e.c->vertex(e.i2)), n->index(e.c->vertex(i3))};
  }

  Candidate compute_value(const Edge_facet& e)
  {
    const Cell_handle c = e.c;
    const int i = e.i, i1 = e.i1, i2 = e.i2, i3 = 6 - e.i - i1 - i2;
    double min_valueP = NOT_VALID_CANDIDATE, min_valueA = infinity;
    Cell_handle min_c;
    int min_i = 0;
    Id min_vn = none;
    bool border_facet = false;
    const Point& p1 = c->vertex(i1)->point();
    const Point& p2 = c->vertex(i2)->point();
    const Point& pc = c->vertex(i3)->point();
    const Vector P2P1 = gt.construct_vector_3_object()(p2, p1);
    const Vector v1 = gt.construct_cross_product_vector_3_object()(gt.construct_vector_3_object()(p2, pc), P2P1);
    const double norm1 = v1 * v1;
    const double norm12 = P2P1 * P2P1;

    Edge_facet e_it = next(e);
    do
    {
      const Cell_handle neigh = e_it.c;
      const int n_ind = e_it.i;
      if(!cas.is_infinite(neigh, n_ind))
      {
        const int n_i1 = e_it.i1, n_i2 = e_it.i2, n_i3 = 6 - n_ind - n_i1 - n_i2;
        const double tmp = priority(neigh, n_ind);
        const Id vn = rank(neigh, n_i3);
        if(tmp != infinity && not_interior(vn)
           && !is_interior_edge(std::make_pair(rank(neigh, n_i1), vn))
           && !is_interior_edge(std::make_pair(rank(neigh, n_i2), vn)))
        {
          const Point& pn = neigh->vertex(n_i3)->point();
          const Vector P2Pn = gt.construct_vector_3_object()(p2, pn);
          const Vector v2 = gt.construct_cross_product_vector_3_object()(P2P1, P2Pn);
          const double norm = std::sqrt(norm1 * gt.compute_scalar_product_3_object()(v2, v2));
          const double pscal = v1 * v2;
          const bool sliver_facet = pscal <= COS_ALPHA_SLIVER * norm;
          if(!sliver_facet && tmp < min_valueA)
          {
            const Vector PnP1 = p1 - pn;
            border_facet =
              !((P2P1 * P2Pn >= -DELTA * std::sqrt(norm12 * gt.compute_scalar_product_3_object()(P2Pn, P2Pn)))
                && (P2P1 * PnP1 >= -DELTA * std::sqrt(norm12 * gt.compute_scalar_product_3_object()(PnP1, PnP1))));
            min_c = neigh;
            min_i = n_ind;
            min_vn = vn;
            min_valueA = tmp;
            min_valueP = pscal / norm;
          }
        }
      }
      e_it = next(e_it);
    } while(e_it.c != c);

    Candidate result;
    result.facet = e;
    Search& search = result.search;
    search = Search{min_valueA, min_valueP, 0, min_vn, min_valueA == infinity || border_facet};
    if(search.not_valid)
      result.candidate = e;
    else
    {
      result.candidate = Edge_facet{min_c, min_c->index(c->vertex(i1)), min_c->index(c->vertex(i2)), min_i};
      if(min_valueP <= COS_BETA)
        search.own = priority(c, i);
    }
    classify(result);
    return result;
  }

  // The criterion of a border edge from its search, for the current K.
  void classify(Candidate& e)
  {
    const Search& s = e.search;
    if(s.not_valid)
      e.value = NOT_VALID_CANDIDATE;
    else if(s.cos > COS_BETA)
      e.value = -(1. + 1. / s.best);
    else if(s.best <= K * s.own)
      e.value = -s.cos;
    else
    {
      e.value = STANDBY_CANDIDATE;
      min_K = (std::min)(min_K, s.best / s.own);
    }
  }

  // compute_value() again for a border edge, its search kept while its best
  // facet may still be taken: the facets that may be taken only get fewer (a
  // vertex made interior stays so, and an interior edge), so the first
  // smallest of them stays the same, and "none" stays none.
  Candidate re_compute_value(const Candidate& e)
  {
    const Search& s = e.search;
    if(s.best_vertex != none)
    {
      const Id v1 = rank(e.facet.c, e.facet.i1), v2 = rank(e.facet.c, e.facet.i2), vn = s.best_vertex;
      if(!not_interior(vn) || is_interior_edge(std::make_pair(v1, vn)) || is_interior_edge(std::make_pair(v2, vn)))
        return compute_value(e.facet);
    }
    Candidate result = e;
    classify(result);
    return result;
  }

  // --- seeding -------------------------------------------------------------
  // The finite facets are in CGAL's order by 4 cell index + i, each once,
  // from its cell of smaller index (the cells' order is the triangulation's).
  bool all_exterior(Cell_handle c, int i) const
  {
    return is_exterior(rank(c, (i + 1) & 3)) && is_exterior(rank(c, (i + 2) & 3))
           && is_exterior(rank(c, (i + 3) & 3));
  }

  // `visit(c, i, facet, partial)` for every finite facet (c, i), each once
  // from its cell of smaller index (`facet` = 4 c->cell_index() + i), in
  // chunks of cells side by side on TBB's threads, each chunk into a
  // partial result of its own from `make()`: the partial results in the
  // chunks' order.
  template <class MakePartial, class Visit>
  std::vector<decltype(std::declval<MakePartial&>()())> finite_facets_in_chunks(MakePartial make, Visit visit)
  {
    auto partial = partial_results_in_chunks<Parallel_if_available_tag>(
      cells_by_index.size(), make, [&](std::size_t begin, std::size_t end, auto& chunk) {
        for(std::size_t k = begin; k < end; ++k)
        {
          if((k - begin) % 4096 == 0 && interruption.stop_requested())
            return;
          const Cell_handle c = cells_by_index[k];
          for(int i = 0; i < 4; ++i)
            if(k < c->neighbor(i)->cell_index() && !cas.is_infinite(c, i))
              visit(c, i, 4 * std::uint64_t(k) + std::uint64_t(i), chunk);
        }
      });
    interruption.throw_if_stop_was_requested();
    return partial;
  }

  bool init(bool re_init)
  {
    Cell_handle min_c;
    int min_i = 0;
    double min_value = infinity;
    if(!re_init)
    {
      // every vertex is exterior: the seeding's test is made once; the
      // first smallest facet is found in chunks of cells side by side, the
      // first smallest of the first chunk that has the smallest value
      if(!seeding.may_seed(*this))
        return false;
      struct Best
      {
        double value;
        std::uint64_t facet;
      };
      const std::vector<Best> best = finite_facets_in_chunks(
        [&]() { return Best{infinity, 0}; }, [&](Cell_handle c, int i, std::uint64_t facet, Best& chunk) {
          const double value = facet_priority(c, i);
          if(value < chunk.value)
            chunk = Best{value, facet};
        });
      for(const Best& chunk : best)
        if(chunk.value < min_value)
        {
          min_value = chunk.value;
          min_c = cells_by_index[chunk.facet / 4];
          min_i = int(chunk.facet % 4);
        }
    }
    else
    {
      // The facets whose vertices are all exterior only get fewer: they
      // are listed once, sorted by priority and then by their order (the
      // first smallest one is CGAL's choice), and each seeding takes the
      // first one still all exterior.
      if(!seeds_ready)
      {
        seeds_ready = true;
        // listed in chunks of cells side by side, then sorted
        typedef std::vector<std::pair<double, std::uint64_t> > Seeds;
        const std::vector<Seeds> chunks = finite_facets_in_chunks(
          []() { return Seeds(); }, [&](Cell_handle c, int i, std::uint64_t facet, Seeds& chunk) {
            if(!all_exterior(c, i))
              return;
            const double value = facet_priority(c, i);
            if(value != infinity)
              chunk.emplace_back(value, facet);
          });
        for(const Seeds& chunk : chunks)
          seeds.insert(seeds.end(), chunk.begin(), chunk.end());
        sort_distinct<Parallel_if_available_tag>(seeds.begin(), seeds.end(), std::less<>());
      }
      while(next_seed < seeds.size())
      {
        const Cell_handle c = cells_by_index[seeds[next_seed].second / 4];
        const int i = int(seeds[next_seed].second % 4);
        if(all_exterior(c, i))
          break;
        ++next_seed;
      }
      if(next_seed == seeds.size())
        return false;
      // CGAL asks the priority of every all-exterior facet: the seeding's
      // test is made on the first one, and is the same for the others
      if(!seeding.may_seed(*this))
        return false;
      min_c = cells_by_index[seeds[next_seed].second / 4];
      min_i = int(seeds[next_seed].second % 4);
      min_value = seeds[next_seed].first;
    }
    if(min_value == infinity)
      return false;

    const int ind = min_i, i1 = (ind + 1) & 3, i2 = (ind + 2) & 3, i3 = (ind + 3) & 3;
    const Candidate e12 = compute_value(Edge_facet{min_c, i1, i2, ind});
    const Candidate e23 = compute_value(Edge_facet{min_c, i2, i3, ind});
    const Candidate e31 = compute_value(Edge_facet{min_c, i3, i1, ind});
    const Id w1 = rank(min_c, i1), w2 = rank(min_c, i2), w3 = rank(min_c, i3);
    const Id p12 = set_border_elt(w1, w2, Border_elt{e12, 1});
    const Id p23 = set_border_elt(w2, w3, Border_elt{e23, 1});
    const Id p31 = set_border_elt(w3, w1, Border_elt{e31, 1});
    inc_mark(w1);
    inc_mark(w2);
    inc_mark(w3);
    insert(e12.value, p12);
    insert(e23.value, p23);
    insert(e31.value, p31);
    select_facet(min_c, ind);
    return true;
  }
  std::vector<Cell_handle> cells_by_index;

  // --- growth --------------------------------------------------------------
  int test_merge(const std::pair<Id, Id>& ordered_key, const Border_elt& result, Id v, double ear_alpha)
  {
    const Edge_facet& ifacet = result.candidate.facet;
    const Point& p1 = vertex_point(ordered_key.first);
    const Point& p2 = vertex_point(ordered_key.second);
    const Point& pc = vertex_point(v);
    const Cell_handle neigh = ifacet.c;
    const int n_ind = ifacet.i, n_i3 = 6 - n_ind - ifacet.i1 - ifacet.i2;
    const Point& pn = neigh->vertex(n_i3)->point();
    const Vector v1 = gt.construct_cross_product_vector_3_object()(gt.construct_vector_3_object()(p2, pc),
                                                                   gt.construct_vector_3_object()(p2, p1));
    const Vector v2 = gt.construct_cross_product_vector_3_object()(gt.construct_vector_3_object()(p2, p1),
                                                                   gt.construct_vector_3_object()(p2, pn));
    const double norm =
      std::sqrt(gt.compute_scalar_product_3_object()(v1, v1) * gt.compute_scalar_product_3_object()(v2, v2));
    if(v1 * v2 > COS_BETA * norm)
      return 1;
    if(ear_alpha <= K * priority(neigh, n_ind))
      return 2;
    return 0;
  }

  void force_merge(const std::pair<Id, Id>& ordered_key, const Border_elt& result)
  {
    const Id r = border_elt(ordered_key.first, ordered_key.second);
    if(r != none)
    {
      wake(r);
      ordered_border.erase(Key(result.candidate.value, r));
    }
    else
      ++anomalies;
    remove_border_edge(ordered_key.first, ordered_key.second);
  }

  void merge_ear(const std::pair<Id, Id>& ordered_el1, const Border_elt& result1, const std::pair<Id, Id>& ordered_key,
                 Id v1, Id v2, const Edge_facet& edge_Ifacet_2)
  {
    remove_border_edge(ordered_key.first, ordered_key.second);
    force_merge(ordered_el1, result1);
    const Candidate e2 = compute_value(edge_Ifacet_2);
    Id p2;
    if(ordered_el1.first == v1)
      p2 = set_border_elt(v2, ordered_el1.second, Border_elt{e2, result1.border});
    else
      p2 = set_border_elt(ordered_el1.first, v2, Border_elt{e2, result1.border});
    dec_mark(v1);
    insert(e2.value, p2);
    dequeue_incidence_request(v2);
    dequeue_incidence_request(ordered_el1.first == v1 ? ordered_el1.second : ordered_el1.first);
  }

  void border_extend(const std::pair<Id, Id>& ordered_key, const Border_elt& result12, Id v1, Id v2, Id v3,
                     const Candidate& e1, const Candidate& e2, Id& p1, Id& p2)
  {
    remove_border_edge(ordered_key.first, ordered_key.second);
    if(is_on_border(v3))
      dequeue_incidence_request(v3);
    if(ordered_key.first == v1)
    {
      p1 = set_border_elt(v1, v3, Border_elt{e1, result12.border});
      p2 = set_border_elt(v3, v2, Border_elt{e2, result12.border});
    }
    else
    {
      p2 = set_border_elt(v2, v3, Border_elt{e2, result12.border});
      p1 = set_border_elt(v3, v1, Border_elt{e1, result12.border});
    }
    inc_mark(v3);
    dequeue_incidence_request(v1);
    dequeue_incidence_request(v2);
  }

  Validation_case validate(const Edge_facet& edge_Efacet, double value)
  {
    const int i = 6 - edge_Efacet.i - edge_Efacet.i1 - edge_Efacet.i2;
    const Cell_handle c = edge_Efacet.c;
    const Id v1 = rank(c, edge_Efacet.i1), v2 = rank(c, edge_Efacet.i2), vi = rank(c, i);
    std::pair<Id, Id> ordered_el1(vi, v1), ordered_el2(vi, v2), ordered_key(v1, v2);
    Border_elt result1, result2, result12;
    if(!is_border_elt(ordered_key, result12))
      ++anomalies;  // CGAL: "probleme coherence bord"
    const bool is_border_el1 = is_border_elt(ordered_el1, result1);
    const bool is_border_el2 = is_border_elt(ordered_el2, result2);

    if(!not_interior(vi) || is_interior_edge(ordered_el1) || is_interior_edge(ordered_el2))
      return NOT_VALID;
    if(is_border_el1 && is_border_el2)
    {
      remove_border_edge(ordered_key.first, ordered_key.second);
      force_merge(ordered_el1, result1);
      force_merge(ordered_el2, result2);
      dec_mark(v1);
      dec_mark(v2);
      dec_mark(vi);
      select_facet(c, edge_Efacet.i);
      return FINAL_CASE;
    }
    if(is_border_el1)
    {
      merge_ear(ordered_el1, result1, ordered_key, v1, v2, Edge_facet{c, i, edge_Efacet.i2, edge_Efacet.i});
      select_facet(c, edge_Efacet.i);
      return EAR_CASE;
    }
    if(is_border_el2)
    {
      merge_ear(ordered_el2, result2, ordered_key, v2, v1, Edge_facet{c, i, edge_Efacet.i1, edge_Efacet.i});
      select_facet(c, edge_Efacet.i);
      return EAR_CASE;
    }
    const Edge_facet edge_Ifacet_1{c, i, edge_Efacet.i1, edge_Efacet.i};
    const Edge_facet edge_Ifacet_2{c, i, edge_Efacet.i2, edge_Efacet.i};
    if(is_exterior(vi))
    {
      const Candidate e1 = compute_value(edge_Ifacet_1);
      const Candidate e2 = compute_value(edge_Ifacet_2);
      Id p1, p2;
      border_extend(ordered_key, result12, v1, v2, vi, e1, e2, p1, p2);
      insert(e1.value, p1);
      insert(e2.value, p2);
      select_facet(c, edge_Efacet.i);
      return EXTERIOR_CASE;
    }

    // vi is on another stretch of the border: joined when one of the two
    // ears it makes closes on a border edge of the same orientation
    Candidate e1 = compute_value(edge_Ifacet_1);
    Candidate e2 = compute_value(edge_Ifacet_2);
    if(e1.value >= STANDBY_CANDIDATE && e2.value >= STANDBY_CANDIDATE)
      return NOT_VALID_CONNECTING_CASE;
    const Edge_facet ear1 = e1.candidate, ear2 = e2.candidate;
    const int ear1_i = 6 - ear1.i - ear1.i1 - ear1.i2;
    const int ear2_i = 6 - ear2.i - ear2.i1 - ear2.i2;
    std::pair<Id, Id> ear1_e, ear2_e;
    if(ordered_key.first == v1)
    {
      ear1_e = std::make_pair(vi, rank(ear1.c, ear1_i));
      ear2_e = std::make_pair(rank(ear2.c, ear2_i), vi);
    }
    else
    {
      ear1_e = std::make_pair(rank(ear1.c, ear1_i), vi);
      ear2_e = std::make_pair(vi, rank(ear2.c, ear2_i));
    }
    Border_elt result_ear1, result_ear2;
    const bool is_border_ear1 = is_ordered_border_elt(ear1_e, result_ear1);
    const bool is_border_ear2 = is_ordered_border_elt(ear2_e, result_ear2);
    bool ear1_valid = false, ear2_valid = false;
    if(is_border_ear1 && e1.value < STANDBY_CANDIDATE && e1.value <= value && result12.border == result_ear1.border)
      ear1_valid = test_merge(ear1_e, result_ear1, v1, priority(ear1.c, ear1.i)) != 0;
    if(is_border_ear2 && e2.value < STANDBY_CANDIDATE && e2.value <= value && result12.border == result_ear2.border)
      ear2_valid = test_merge(ear2_e, result_ear2, v2, priority(ear2.c, ear2.i)) != 0;
    if(!ear1_valid && !ear2_valid)
      return NOT_VALID_CONNECTING_CASE;

    Id p1, p2;
    border_extend(ordered_key, result12, v1, v2, vi, e1, e2, p1, p2);
    if(ear1_valid && ear2_valid && ear1_e == ear2_e)
    {
      if(e1.value < e2.value)
      {
        const Validation_case res = validate(ear1, e1.value);
        if(res != EAR_CASE && res != FINAL_CASE)
          ++anomalies;
        e2 = compute_value(edge_Ifacet_2);
        p2 = ordered_key.first == v1 ? set_again_border_elt(vi, v2, Border_elt{e2, result2.border})
                                     : set_again_border_elt(v2, vi, Border_elt{e2, result2.border});
        insert(e2.value, p2);
      }
      else
      {
        const Validation_case res = validate(ear2, e2.value);
        if(res != EAR_CASE && res != FINAL_CASE)
          ++anomalies;
        e1 = compute_value(edge_Ifacet_1);
        p1 = ordered_key.first == v1 ? set_again_border_elt(v1, vi, Border_elt{e1, result1.border})
                                     : set_again_border_elt(vi, v1, Border_elt{e1, result1.border});
        insert(e1.value, p1);
      }
    }
    else
    {
      if(ear1_valid)
      {
        const Validation_case res = validate(ear1, e1.value);
        if(res != EAR_CASE && res != FINAL_CASE)
          ++anomalies;
      }
      if(ear2_valid)
      {
        const Validation_case res = validate(ear2, e2.value);
        if(res != EAR_CASE && res != FINAL_CASE)
          ++anomalies;
      }
      if(!ear1_valid)
        insert(e1.value, p1);
      if(!ear2_valid)
        insert(e2.value, p2);
    }
    select_facet(c, edge_Efacet.i);
    return CONNECTING_CASE;
  }

  // Every border edge re-evaluated for the current K (the edges asleep
  // would be left as they are: they stay asleep).
  void re_compute_values()
  {
    std::vector<Key> recomputed;
    pass_output = &recomputed;
    while(!ordered_border.empty())
    {
      const Key key_at = ordered_border.front();
      pass_key = &key_at;
      const Candidate stored = records[key_at.second].elt.candidate;
      const Edge_facet mem = stored.facet;
      ordered_border.pop_front();
      Candidate new_candidate = re_compute_value(stored);
      if(new_candidate.value == STANDBY_CANDIDATE)
        new_candidate.value = STANDBY_CANDIDATE_BIS;
      Border_elt result;
      std::pair<Id, Id> key(rank(mem.c, mem.i1), rank(mem.c, mem.i2));
      is_border_elt(key, result);
      const Id pnew = set_again_border_elt(key.first, key.second, Border_elt{new_candidate, result.border});
      if(pnew != none)
        recomputed.push_back(Key(new_candidate.value, pnew));
    }
    pass_key = nullptr;
    pass_output = nullptr;
    // the keys recomputed are the border again, but for the records left
    // "not valid" by their last write (one may be written twice in the
    // pass), which go to sleep
    ordered_border.clear();
    for(const Key& k : recomputed)
      if(k.first != NOT_VALID_CANDIDATE || records[k.second].elt.candidate.value != NOT_VALID_CANDIDATE)
        ordered_border.insert(k);
      else if(!asleep[k.second])
        put_to_sleep(k.second);
  }

  void extend()
  {
    K = K_init;
    double K_prev = K;
    if(border_is_empty())
      return;
    do
    {
      min_K = infinity;
      do
      {
        const double value = smallest_criterion();
        if(value >= STANDBY_CANDIDATE)
          re_compute_values();
        else
        {
          const Candidate stored = records[ordered_border.front().second].elt.candidate;
          const Edge_facet candidate = stored.candidate;
          const Edge_facet mem = stored.facet;
          const Candidate mem_e_it{value, mem, candidate, stored.search};
          const Id v1 = rank(mem.c, mem.i1), v2 = rank(mem.c, mem.i2);
          const int i3 = 6 - candidate.i1 - candidate.i2 - candidate.i;
          ordered_border.pop_front();
          const Validation_case validate_result = validate(candidate, value);
          if(validate_result == NOT_VALID || validate_result == NOT_VALID_CONNECTING_CASE)
          {
            Border_elt result;
            std::pair<Id, Id> key(v1, v2);
            is_border_elt(key, result);
            if(validate_result == NOT_VALID_CONNECTING_CASE)
              set_incidence_request(rank(candidate.c, i3), value, key);
            else
            {
              const Candidate new_candidate = re_compute_value(stored);
              if(new_candidate != mem_e_it)
                insert(new_candidate.value, set_again_border_elt(key.first, key.second, Border_elt{new_candidate, result.border}));
            }
          }
        }
      } while(!border_is_empty() && smallest_criterion() < STANDBY_CANDIDATE_BIS);
      K_prev = K;
      K += (std::max)(K_step, min_K - K + eps);
    } while(!border_is_empty() && K <= K && min_K != infinity && K != K_prev);
  }

  template <class... Vectors>
  static void release(Vectors&... v)
  {
    (Vectors().swap(v), ...);
  }

  const Point& vertex_point(Id v) const { return vertex_by_rank[v]->point(); }
  std::vector<Vertex_handle> vertex_by_rank;

public:
  // Grows the front; the selected facets are then read by `soup()`.
  void run()
  {
    const std::size_t n = cas.number_of_vertices() + 1;  // with the infinite vertex
    rank_of_index.assign(cas.number_of_vertices(), none);
    vertex_by_rank.reserve(n);
    for(auto v = cas.tds().vertices_begin(); v != cas.tds().vertices_end(); ++v)
    {
      const Id r = Id(vertex_by_rank.size());
      if(Vertex_handle(v) == cas.infinite_vertex())
        infinite_rank = r;
      else
        rank_of_index[v->vertex_index()] = r;
      vertex_by_rank.push_back(v);
    }
    cells_by_index.resize(cas.number_of_cells());
    for(auto c = cas.tds().cells_begin(); c != cas.tds().cells_end(); ++c)
      cells_by_index[c->cell_index()] = c;
    mark.assign(n, -1);
    first_record.resize(n);
    second_record.resize(n);
    for(std::size_t r = 0; r < n; ++r)
    {
      first_record[r] = Id(2 * r);
      second_record[r] = Id(2 * r + 1);
    }
    records.assign(2 * n, Record());
    interior_head.assign(n, none);
    request_head.assign(n, none);
    request_tail.assign(n, none);
    asleep.assign(2 * n, 0);
    ordered_border.reset(2 * n);
    watch_head.assign(n, none);

    K = 5;
    COS_BETA = std::cos(0.52);
    min_K = infinity;
    bool re_init = false;
    do
    {
      ++number_of_components;
      re_init = init(re_init);
      if(re_init)
      {
        extend();
        // CGAL's postprocessing, that removes no vertex (see above)
        if(number_of_selected > int(cas.number_of_vertices()))
          for(std::size_t r = 0; r < n; ++r)
            if(Id(r) != infinite_rank)
              erase_incidence_request(Id(r));
      }
    } while(re_init);
    // the growth's state, that surface() does not read, freed before the
    // memory peak that surface() makes
    release(mark, first_record, second_record, records, interior_head, interiors, request_head, request_tail,
            requests, asleep, watch_head, watches, seeds, cells_by_index, vertex_by_rank);
    ordered_border = Key_set();
  }

  // The selected facets as CGAL's advancing front leaves them: its faces
  // are created in the order of the finite facets (each facet's first cell
  // first), each in the vertex order of its selected side, paired on their
  // edges in that order; the border edges, by their vertices' order, get an
  // infinite face each (paired around their vertex in that order), and
  // `reorient_faces()` turns each connected set of faces to agree with its
  // first face, a face turned taking its facet from its other side (so its
  // value too: the facet's conformal value differs in the last bits from
  // one side to the other). The soup's vertices are numbered in the order
  // of the turned faces, as `cgal_front_triangles()` numbers them.
  Advancing_front_soup surface() const
  {
    const std::size_t no = std::size_t(-1);
    Advancing_front_soup soup;
    std::vector<std::pair<Cell_handle, int> > facets;
    std::vector<std::size_t> soup_vertex(cas.number_of_vertices(), Advancing_front_soup::no_neighbor);
    auto add = [&](Cell_handle c, int i) {
      std::array<std::size_t, 3> triangle;
      for(int k = 0; k < 3; ++k)
        triangle[k] = soup_vertex_of(soup, soup_vertex, c->vertex((i + 1 + k) & 3)->vertex_index());
      soup.triangles.push_back(triangle);
      facets.emplace_back(c, i);
    };
    // the order of the finite facets (see "seeding"), a facet's first
    // cell's side first: sorted rather than found by a walk over every facet
    {
      std::vector<std::pair<std::uint64_t, std::size_t> > order(selected.size());
      for_each_index<Parallel_if_available_tag>(selected.size(), []() { return 0; }, [&](std::size_t k, int&) {
        const Cell_handle c = selected[k].first, n = c->neighbor(selected[k].second);
        const bool first = c->cell_index() < n->cell_index();
        const std::uint64_t facet = first ? std::uint64_t(c->cell_index()) * 4 + std::uint64_t(selected[k].second)
                                          : std::uint64_t(n->cell_index()) * 4 + std::uint64_t(n->index(c));
        order[k] = std::make_pair(2 * facet + (first ? 0 : 1), k);
      });
      sort_distinct<Parallel_if_available_tag>(order.begin(), order.end(), std::less<>());
      for(const auto& o : order)
        add(selected[o.second].first, selected[o.second].second);
    }
    soup_vertex = std::vector<std::size_t>();
    pair_neighbors(soup);

    // the faces: the soup's triangles, then the infinite ones
    const std::size_t nt = soup.triangles.size(), nv = soup.shape_vertex.size();
    const std::size_t infinite_vertex = no - 1;
    std::vector<std::array<std::size_t, 3> > V(soup.triangles), N(soup.neighbors);
    std::vector<char> turned(nt, 0);
    {
      auto vertex_rank = [&](std::size_t s) { return rank_of_index[soup.shape_vertex[s]]; };
      std::vector<std::pair<std::pair<Id, Id>, std::size_t> > border;  // (ranks, corner 3 t + k)
      for(std::size_t t = 0; t < nt; ++t)
        for(int k = 0; k < 3; ++k)
          if(N[t][k] == no)
          {
            const Id a = vertex_rank(V[t][(k + 2) % 3]), b = vertex_rank(V[t][(k + 1) % 3]);
            border.emplace_back(std::make_pair((std::min)(a, b), (std::max)(a, b)), 3 * t + std::size_t(k));
          }
      sort_distinct<Parallel_if_available_tag>(border.begin(), border.end(), std::less<>());
      std::vector<std::size_t> pending(nv, no);  // by vertex: an infinite face's corner 3 f + idx
      for(const auto& e : border)
      {
        const std::size_t t = e.second / 3;
        const int k = int(e.second % 3);
        const std::size_t f = V.size();
        const std::size_t a = V[t][(k + 2) % 3], b = V[t][(k + 1) % 3];
        V.push_back({{infinite_vertex, a, b}});
        N.push_back({{t, no, no}});
        N[t][std::size_t(k)] = f;
        for(const std::pair<std::size_t, int>& edge : {std::make_pair(b, 1), std::make_pair(a, 2)})
        {
          std::size_t& p = pending[edge.first];
          if(p == no)
            p = 3 * f + std::size_t(edge.second);
          else
          {
            N[f][std::size_t(edge.second)] = p / 3;
            N[p / 3][p % 3] = f;
            p = no;
          }
        }
      }
    }
    {
      const std::size_t nf = V.size();
      std::vector<char> oriented(nf, 0);
      std::vector<std::size_t> stack;
      std::size_t left = nf, fit = 0;
      auto cw = [](std::size_t i) { return (i + 2) % 3; };
      auto ccw = [](std::size_t i) { return (i + 1) % 3; };
      while(left != 0)
      {
        while(oriented[fit])
          ++fit;
        oriented[fit] = 1;
        --left;
        stack.push_back(fit);
        while(!stack.empty())
        {
          const std::size_t fh = stack.back();
          stack.pop_back();
          for(std::size_t ih = 0; ih < 3; ++ih)
          {
            const std::size_t fn = N[fh][ih];
            if(fn == no || oriented[fn])
              continue;
            oriented[fn] = 1;
            std::size_t in = 0;
            while(in < 3 && N[fn][in] != fh)
              ++in;
            if(in < 3 && V[fn][cw(in)] != V[fh][ccw(ih)])
            {
              std::swap(V[fn][0], V[fn][1]);
              std::swap(N[fn][0], N[fn][1]);
              if(fn < nt)
                turned[fn] ^= 1;
            }
            --left;
            stack.push_back(fn);
          }
        }
      }
    }

    // the turned faces, their values, their vertices renumbered in order
    Advancing_front_soup out;
    out.triangles.reserve(nt);
    out.neighbors.reserve(nt);
    out.values.resize(nt);
    for_each_index<Parallel_if_available_tag>(nt, []() { return 0; }, [&](std::size_t t, int&) {
      Cell_handle c = facets[t].first;
      int i = facets[t].second;
      if(turned[t])
      {
        const Cell_handle n = c->neighbor(i);
        i = n->index(c);
        c = n;
      }
      out.values[t] = double(cas.conformal_alpha(c, i));
    });
    std::vector<std::size_t> new_vertex(nv, no);
    for(std::size_t t = 0; t < nt; ++t)
    {
      std::array<std::size_t, 3> triangle, neighbor;
      for(int k = 0; k < 3; ++k)
      {
        std::size_t& s = new_vertex[V[t][k]];
        if(s == no)
        {
          s = out.shape_vertex.size();
          out.shape_vertex.push_back(soup.shape_vertex[V[t][k]]);
        }
        triangle[k] = s;
        neighbor[k] = N[t][k] < nt ? N[t][k] : Advancing_front_soup::no_neighbor;
      }
      out.triangles.push_back(triangle);
      out.neighbors.push_back(neighbor);
    }
    return out;
  }
};

// The front's triangles in its order, oriented as CGAL's front orients
// them, with their values and neighbors (those of `cgal_front_triangles()`
// after `pair_neighbors()`). `anomalies`, if given, counts the states in
// which CGAL's front would have printed a warning or written through a null
// pointer (none expected).
template <class Cas>
Advancing_front_soup conformal_front_triangles(const Cas& cas, std::size_t* anomalies = nullptr)
{
  if(cas.dimension() < 3)
    return Advancing_front_soup();
  Conformal_front<Cas> front(cas);
  front.run();
  if(anomalies != nullptr)
    *anomalies = front.number_of_anomalies();
  return front.surface();
}

// The triangle soup grown facet by facet over the finite Delaunay facets,
// smaller conformal values first, with no bound on the scale. The front
// only grows where the surface stays an oriented 2-manifold, so the soup is
// one sheet per part of the sampled surface, closed or with a border,
// consistently oriented within each part, in the canonical order. The soup
// at a scale `a` is cut from it (`pruned_soup()`), so that one front serves
// every scale.
template <class Cas>
Advancing_front_soup conformal_front_soup(const Cas& cas, std::size_t* anomalies = nullptr)
{
  Interruption_point interruption;
  Advancing_front_soup soup = conformal_front_triangles(cas, anomalies);
  interruption.throw_if_stopped();
  put_in_canonical_order(soup);
  return soup;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CONFORMAL_FRONT_H
