// Builds the conformal alpha shape filtration of a point cloud and prints its
// spectrum and the classification counts at the paper's scales.
//   conformal_alpha_shape_example [points.xyz]   (default: the bundled bunny)
#include <CGAL/Conformal_alpha_shape_3.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_data_structure_3<CGAL::Conformal_alpha_shape_vertex_base_3<K>,
                                             CGAL::Conformal_alpha_shape_cell_base_3<K> > Tds;
typedef CGAL::Conformal_alpha_shape_3<CGAL::Delaunay_triangulation_3<K, Tds> > Conformal_alpha_shape;

int main(int argc, char* argv[])
{
  const char* filename = argc > 1 ? argv[1] : CGAL_CAS3_DEFAULT_INPUT;
  std::vector<K::Point_3> points;
  if(!CGAL::IO::read_points(filename, std::back_inserter(points)))
  {
    std::cerr << "cannot read points from " << filename << "\n";
    return EXIT_FAILURE;
  }

  Conformal_alpha_shape cas(points.begin(), points.end());
  std::cout << filename << ": " << cas.number_of_input_points() << " points, "
            << cas.number_of_vertices() << " vertices, " << cas.number_of_finite_cells()
            << " cells\n"
            << "spectrum: " << cas.number_of_alphas() << " distinct conformal values from "
            << cas.get_nth_alpha(1) << " to " << cas.get_nth_alpha(cas.number_of_alphas()) << "\n\n"
            << "facets by class at the paper's scales, and solid components\n"
            << "quantile  a           singular  regular  interior  solids\n";
  for(double q : {0.10, 0.25, 0.35, 0.50})
  {
    cas.set_alpha(cas.alpha_at_quantile(q));
    std::size_t counts[4] = {0, 0, 0, 0};
    for(const auto& f : cas.finite_facets())
      ++counts[cas.classify(f)];
    std::cout << "   " << int(100 * q) << "%    " << cas.get_alpha() << "   "
              << counts[Conformal_alpha_shape::SINGULAR] << "   "
              << counts[Conformal_alpha_shape::REGULAR] << "   "
              << counts[Conformal_alpha_shape::INTERIOR] << "   "
              << cas.number_of_solid_components() << "\n";
  }
  return EXIT_SUCCESS;
}
