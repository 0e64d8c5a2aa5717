#include <CGAL/Conformal_alpha_shape_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_data_structure_3<CGAL::Conformal_alpha_shape_vertex_base_3<K>,
                                             CGAL::Conformal_alpha_shape_cell_base_3<K> > Tds;
typedef CGAL::Conformal_alpha_shape_3<CGAL::Delaunay_triangulation_3<K, Tds> > Cas;

int main()
{
  const std::vector<K::Point_3> pts = {K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0),
                                       K::Point_3(0, 0, 1), K::Point_3(1, 1, 1)};
  Cas cas(pts.begin(), pts.end());
  std::cout << "consumer: " << cas.number_of_finite_cells() << " cells\n";
  return cas.number_of_finite_cells() == 2 ? 0 : 1;
}
