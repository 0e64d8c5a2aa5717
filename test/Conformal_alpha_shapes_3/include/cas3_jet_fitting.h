// The peer of the accuracy measurements (the manual, "Measured: Advancing
// Front against the Solid Boundary"; METHOD.md section 7): CGAL's
// Monge_via_jet_fitting, degree 2 jet and degree 2 Monge form, on the k
// nearest neighbors of a point (the point included), its normal's sign
// taken from the truth. For evaluate_surfaces and the tests.
#ifndef CAS3_JET_FITTING_H
#define CAS3_JET_FITTING_H

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace cas3_test {

// The q-quantile of `v` (the element of rank q n); NaN when empty.
inline double quantile(std::vector<double> v, double q)
{
  if(v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  const std::size_t k = (std::min)(v.size() - 1, std::size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return v[k];
}

inline double median_abs(const std::vector<double>& v)
{
  std::vector<double> a;
  a.reserve(v.size());
  for(double x : v) a.push_back(std::abs(x));
  return quantile(a, 0.5);
}

// Jet fitting's values at some points, per k.
template <class Kernel>
struct Jet_estimates
{
  std::vector<std::vector<typename Kernel::Vector_3> > normal;  // [k][point]
  std::vector<std::vector<double> > H, K;                       // [k][point]
};

// Jet fitting at the points `index` of `points` with each k of `ks` (at
// most the number of points), the normal's sign from `truth_normals`;
// convex with an outward normal is positive, as in this package.
template <class Kernel>
Jet_estimates<Kernel> jet_fitting(const std::vector<typename Kernel::Point_3>& points,
                                  const std::vector<typename Kernel::Vector_3>& truth_normals,
                                  const std::vector<std::size_t>& index, const std::vector<int>& ks)
{
  typedef typename Kernel::Point_3 Point;
  typedef CGAL::Search_traits_3<Kernel> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef CGAL::Monge_via_jet_fitting<Kernel> Fitting;
  const typename Search::Tree tree(points.begin(), points.end());
  const int k_max = *std::max_element(ks.begin(), ks.end());
  Jet_estimates<Kernel> out;
  out.normal.resize(ks.size());
  out.H.resize(ks.size());
  out.K.resize(ks.size());
  std::vector<Point> neighbors;
  for(std::size_t i : index)
  {
    neighbors.clear();
    const Search search(tree, points[i], unsigned(k_max));
    for(auto it = search.begin(); it != search.end(); ++it) neighbors.push_back(it->first);
    for(std::size_t j = 0; j < ks.size(); ++j)
    {
      const std::size_t k = (std::min)(std::size_t(ks[j]), neighbors.size());
      Fitting fitting;
      typename Fitting::Monge_form form = fitting(neighbors.begin(), neighbors.begin() + std::ptrdiff_t(k), 2, 2);
      form.comply_wrt_given_normal(truth_normals[i]);
      // Monge form z = (k1 x^2 + k2 y^2) / 2 along the normal: convex with
      // outward normal has k1, k2 < 0 there, > 0 in this package's convention
      const double k1 = -form.principal_curvatures(0), k2 = -form.principal_curvatures(1);
      out.normal[j].push_back(form.normal_direction());
      out.H[j].push_back((k1 + k2) / 2);
      out.K[j].push_back(k1 * k2);
    }
  }
  return out;
}

// Every `step`-th index of [0, n), `step` giving about `samples` of them
// (all when `samples` is 0 or at least n): the points jet fitting is
// measured at.
inline std::vector<std::size_t> spread_indices(std::size_t n, std::size_t samples)
{
  const std::size_t step = samples == 0 || samples >= n ? 1 : n / samples;
  std::vector<std::size_t> index;
  for(std::size_t i = 0; i < n; i += step) index.push_back(i);
  return index;
}

} // namespace cas3_test

#endif // CAS3_JET_FITTING_H
