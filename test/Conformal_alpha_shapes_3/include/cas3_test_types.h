// The types the library's tests share: the kernel, the shape, the meshes
// the BGL functions are tested on, and the pipeline. A test file brings
// them into its own namespace with `using namespace cas3_test_types;`.
#ifndef CAS3_TEST_TYPES_H
#define CAS3_TEST_TYPES_H

#include <CGAL/Conformal_alpha_shape_3.h>
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <boost/mpl/list.hpp>

#include <cstddef>

#include "cas3_analytic_surfaces.h"

namespace cas3_test_types {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Triangulation_data_structure_3<CGAL::Conformal_alpha_shape_vertex_base_3<K>,
                                             CGAL::Conformal_alpha_shape_cell_base_3<K> > Tds;
typedef CGAL::Conformal_alpha_shape_3<CGAL::Delaunay_triangulation_3<K, Tds> > Cas;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
// the two meshes every BGL function is tested on
typedef boost::mpl::list<Surface_mesh, Polyhedron> Mesh_types;
typedef cas3_analytic::Truth_sample<Point, Vector> Sample;
typedef CGAL::Conformal_alpha_shapes_3::Multiscale_curvatures<K> Analysis;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

} // namespace cas3_test_types

namespace cas3_test {

// Under the sanitizers (about ten times slower) the tests run on smaller
// samples: the same properties, a fraction of the work; the documented
// figures are those of the Release sizes. Solid boundaries are checked on
// `closed_points` and `noisy_points`, sheets on `sheet_points`, and the
// curvature accuracy on `curvature_points` with jet fitting measured at
// `jet_samples` of them.
#ifdef CAS3_SANITIZED
const std::size_t closed_points = 8000, noisy_points = 15000, sheet_points = 5000, curvature_points = 5000,
                  jet_samples = 1000;
#else
const std::size_t closed_points = 20000, noisy_points = 50000, sheet_points = 20000, curvature_points = 20000,
                  jet_samples = 5000;
#endif

} // namespace cas3_test

#endif // CAS3_TEST_TYPES_H
