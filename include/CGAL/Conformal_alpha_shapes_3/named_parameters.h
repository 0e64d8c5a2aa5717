// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_NAMED_PARAMETERS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <type_traits>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

// Tags of the package's own named parameters. They live here, not in
// CGAL::internal_np, where later CGAL versions define some of the same names.
namespace internal_np_cas3 {
enum vertex_mean_curvature_map_t { vertex_mean_curvature_map };
enum vertex_Gaussian_curvature_map_t { vertex_Gaussian_curvature_map };
enum vertex_principal_curvatures_and_directions_map_t { vertex_principal_curvatures_and_directions_map };
enum ring_size_t { ring_size };
enum estimator_t { estimator };
enum vertex_input_index_map_t { vertex_input_index_map };
enum face_orientation_group_map_t { face_orientation_group_map };
enum local_feature_size_estimator_t { local_feature_size_estimator };
enum local_feature_sizes_t { local_feature_sizes };
enum coverage_t { coverage };
enum scales_t { scales };
enum reference_normals_t { reference_normals };
enum surface_extraction_t { surface_extraction };
enum denoising_t { denoising };
enum denoising_neighbors_t { denoising_neighbors };
enum neighborhood_radius_t { neighborhood_radius };
enum neighborhood_radii_t { neighborhood_radii };
enum vertex_neighborhood_radius_map_t { vertex_neighborhood_radius_map };
enum neighborhoods_t { neighborhoods };
enum noise_level_t { noise_level };
enum sample_spacing_t { sample_spacing };
enum smoothing_radius_t { smoothing_radius };
enum smoothing_passes_t { smoothing_passes };
enum noise_estimate_t { noise_estimate };
enum fit_center_key_map_t { fit_center_key_map };
enum orient_each_point_t { orient_each_point };
enum vertex_curvature_uncertainty_map_t { vertex_curvature_uncertainty_map };
enum release_shape_t { release_shape };
enum first_point_index_t { first_point_index };
enum center_normal_map_t { center_normal_map };
enum ring_radii_t { ring_radii };
enum ring_weights_t { ring_weights };
enum shape_index_bins_t { shape_index_bins };
enum curvedness_bins_t { curvedness_bins };
enum curvedness_range_t { curvedness_range };
enum geometry_bins_t { geometry_bins };
enum dense_radius_t { dense_radius };
enum thinning_t { thinning };
enum number_of_candidates_t { number_of_candidates };
enum candidate_pool_t { candidate_pool };
enum inlier_tolerance_t { inlier_tolerance };
enum balance_kinds_t { balance_kinds };
} // namespace internal_np_cas3

namespace internal {

// Whether T is a pack of named parameters, to tell overloads apart.
template <typename T>
struct Is_named_function_parameters : std::false_type {};
template <typename T, typename Tag, typename Base>
struct Is_named_function_parameters<CGAL::Named_function_parameters<T, Tag, Base> > : std::true_type {};

} // namespace internal

/// \ingroup PkgConformalAlphaShapes3NamedParameters
/// Named parameters of this package. Each `name(value)` starts a pack and
/// `name(value, np)` adds to the pack `np`, which may hold CGAL's own named
/// parameters; the usual CGAL members (`.vertex_point_map(...)`, ...) chain
/// after either. `combine(np1, np2)` joins two packs.
namespace parameters {

#define CGAL_CAS3_ADD_NAMED_PARAMETER(NAME)                                                     \
  template <typename K>                                                                         \
  CGAL::Named_function_parameters<K, internal_np_cas3::NAME##_t> NAME(const K& k)               \
  {                                                                                             \
    return CGAL::Named_function_parameters<K, internal_np_cas3::NAME##_t>(k);                   \
  }                                                                                             \
  template <typename K, typename T, typename Tag, typename Base>                                \
  CGAL::Named_function_parameters<K, internal_np_cas3::NAME##_t,                                \
                                  CGAL::Named_function_parameters<T, Tag, Base> >               \
  NAME(const K& k, const CGAL::Named_function_parameters<T, Tag, Base>& np)                     \
  {                                                                                             \
    return CGAL::Named_function_parameters<K, internal_np_cas3::NAME##_t,                       \
                                           CGAL::Named_function_parameters<T, Tag, Base> >(k, np); \
  }

CGAL_CAS3_ADD_NAMED_PARAMETER(vertex_mean_curvature_map)
CGAL_CAS3_ADD_NAMED_PARAMETER(vertex_Gaussian_curvature_map)
CGAL_CAS3_ADD_NAMED_PARAMETER(vertex_principal_curvatures_and_directions_map)
CGAL_CAS3_ADD_NAMED_PARAMETER(ring_size)
CGAL_CAS3_ADD_NAMED_PARAMETER(estimator)
CGAL_CAS3_ADD_NAMED_PARAMETER(vertex_input_index_map)
CGAL_CAS3_ADD_NAMED_PARAMETER(face_orientation_group_map)
CGAL_CAS3_ADD_NAMED_PARAMETER(local_feature_size_estimator)
CGAL_CAS3_ADD_NAMED_PARAMETER(local_feature_sizes)
CGAL_CAS3_ADD_NAMED_PARAMETER(coverage)
CGAL_CAS3_ADD_NAMED_PARAMETER(scales)
CGAL_CAS3_ADD_NAMED_PARAMETER(reference_normals)
CGAL_CAS3_ADD_NAMED_PARAMETER(surface_extraction)
CGAL_CAS3_ADD_NAMED_PARAMETER(denoising)
CGAL_CAS3_ADD_NAMED_PARAMETER(denoising_neighbors)
CGAL_CAS3_ADD_NAMED_PARAMETER(neighborhood_radius)
CGAL_CAS3_ADD_NAMED_PARAMETER(neighborhood_radii)
CGAL_CAS3_ADD_NAMED_PARAMETER(vertex_neighborhood_radius_map)
CGAL_CAS3_ADD_NAMED_PARAMETER(neighborhoods)
CGAL_CAS3_ADD_NAMED_PARAMETER(noise_level)
CGAL_CAS3_ADD_NAMED_PARAMETER(sample_spacing)
CGAL_CAS3_ADD_NAMED_PARAMETER(smoothing_radius)
CGAL_CAS3_ADD_NAMED_PARAMETER(smoothing_passes)
CGAL_CAS3_ADD_NAMED_PARAMETER(noise_estimate)
CGAL_CAS3_ADD_NAMED_PARAMETER(fit_center_key_map)
CGAL_CAS3_ADD_NAMED_PARAMETER(orient_each_point)
CGAL_CAS3_ADD_NAMED_PARAMETER(vertex_curvature_uncertainty_map)
CGAL_CAS3_ADD_NAMED_PARAMETER(release_shape)
CGAL_CAS3_ADD_NAMED_PARAMETER(first_point_index)
CGAL_CAS3_ADD_NAMED_PARAMETER(center_normal_map)
CGAL_CAS3_ADD_NAMED_PARAMETER(ring_radii)
CGAL_CAS3_ADD_NAMED_PARAMETER(ring_weights)
CGAL_CAS3_ADD_NAMED_PARAMETER(shape_index_bins)
CGAL_CAS3_ADD_NAMED_PARAMETER(curvedness_bins)
CGAL_CAS3_ADD_NAMED_PARAMETER(curvedness_range)
CGAL_CAS3_ADD_NAMED_PARAMETER(geometry_bins)
CGAL_CAS3_ADD_NAMED_PARAMETER(dense_radius)
CGAL_CAS3_ADD_NAMED_PARAMETER(thinning)
CGAL_CAS3_ADD_NAMED_PARAMETER(number_of_candidates)
CGAL_CAS3_ADD_NAMED_PARAMETER(candidate_pool)
CGAL_CAS3_ADD_NAMED_PARAMETER(inlier_tolerance)
CGAL_CAS3_ADD_NAMED_PARAMETER(balance_kinds)

#undef CGAL_CAS3_ADD_NAMED_PARAMETER

/// The pack holding the parameters of `np1` and of `np2`; where both hold
/// the same parameter, `np1`'s value is used.
template <typename T, typename Tag, typename T2, typename Tag2, typename Base2>
CGAL::Named_function_parameters<T, Tag, CGAL::Named_function_parameters<T2, Tag2, Base2> >
combine(const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& np1,
        const CGAL::Named_function_parameters<T2, Tag2, Base2>& np2)
{
  return {np1.v, np2};
}

template <typename T, typename Tag, typename Base, typename T2, typename Tag2, typename Base2>
auto combine(const CGAL::Named_function_parameters<T, Tag, Base>& np1,
             const CGAL::Named_function_parameters<T2, Tag2, Base2>& np2)
{
  auto rest = combine(static_cast<const Base&>(np1), np2);
  return CGAL::Named_function_parameters<T, Tag, decltype(rest)>(np1.v, rest);
}

} // namespace parameters
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_NAMED_PARAMETERS_H
