# Type stub of conformal_alpha_shapes, for editors and type checkers.
import os
from typing import Any, Callable, Dict, Iterator, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

_Points = npt.ArrayLike
_Item = Union[str, float]

class Layer:
    name: Optional[str]
    a: Optional[float]
    description: Optional[str]
    surface: Optional[Dict[str, float]]
    normal: npt.NDArray[np.float64]
    H: npt.NDArray[np.float64]
    K: npt.NDArray[np.float64]
    k1: npt.NDArray[np.float64]
    k2: npt.NDArray[np.float64]
    d1: npt.NDArray[np.float64]
    d2: npt.NDArray[np.float64]
    radius: npt.NDArray[np.float64]
    source: Optional[npt.NDArray[np.uint8]]
    distance: Optional[npt.NDArray[np.float64]]
    H_sigma: npt.NDArray[np.float64]
    K_sigma: npt.NDArray[np.float64]
    normal_sigma: npt.NDArray[np.float64]
    H_noise_sigma: Optional[npt.NDArray[np.float64]]
    @property
    def shape_index(self) -> npt.NDArray[np.float64]: ...
    @property
    def curvedness(self) -> npt.NDArray[np.float64]: ...
    def __getitem__(self, key: str) -> np.ndarray: ...
    def __len__(self) -> int: ...
    def keys(self) -> List[str]: ...
    def colors(self, key: str = ..., limit: Optional[float] = ...) -> npt.NDArray[np.float64]: ...

class PointCloud(Tuple[npt.NDArray[np.float64], Optional[npt.NDArray[np.float64]]]):
    points: npt.NDArray[np.float64]
    normals: Optional[npt.NDArray[np.float64]]
    fields: Optional[Dict[str, np.ndarray]]
    las: Optional[Dict[str, object]]
    counts: Optional[Dict[str, int]]
    summary: Optional[str]

class Result:
    layers: Tuple[str, ...]
    outlier: npt.NDArray[np.bool_]
    spacing: Optional[float]
    noise: Optional[float]
    denoised: Optional[bool]
    merged: Optional[int]
    @property
    def points(self) -> npt.NDArray[np.float64]: ...
    def __getitem__(self, name: str) -> Layer: ...
    def uncertainty_summary(self) -> Dict[str, Tuple[float, float, Optional[str]]]: ...
    def __iter__(self) -> Iterator[str]: ...
    def __len__(self) -> int: ...
    def to_structured(self, name: str) -> np.ndarray: ...
    def write_las(self, path: Union[str, os.PathLike], cloud: Optional[PointCloud] = ...) -> None: ...
    def to_dataframe(self, name: str) -> Any: ...
    def write_ply(self, path: Union[str, os.PathLike], precision: str = ...) -> str: ...

def read_curvatures(path: Union[str, os.PathLike]) -> Result: ...

def multiscale_curvatures(
    points: _Points,
    normals: Optional[_Points] = ...,
    *,
    scales: Union[_Item, Sequence[_Item]] = ...,
    radii: Union[_Item, Sequence[_Item]] = ...,
    rings: Union[int, Sequence[int]] = ...,
    estimator: str = ...,
    denoise: Union[str, bool] = ...,
    denoise_neighbors: Optional[int] = ...,
    extraction: str = ...,
    threads: Optional[int] = ...,
    progress: Optional[Callable[[str, float], object]] = ...,
    spacing: Optional[float] = ...,
    noise: Optional[float] = ...,
) -> Result: ...

def front_closing_values(
    points: _Points,
    normals: Optional[_Points] = ...,
    *,
    denoise: Union[str, bool] = ...,
    denoise_neighbors: Optional[int] = ...,
    threads: Optional[int] = ...,
    progress: Optional[Callable[[str, float], object]] = ...,
    spacing: Optional[float] = ...,
    noise: Optional[float] = ...,
) -> npt.NDArray[np.float64]: ...

class ConformalAlphaShape:
    def __init__(self, points: _Points, local_scales: Optional[npt.ArrayLike] = ...) -> None: ...
    def __len__(self) -> int: ...
    @property
    def points(self) -> npt.NDArray[np.float64]: ...
    @property
    def dimension(self) -> int: ...
    @property
    def local_feature_sizes(self) -> npt.NDArray[np.float64]: ...
    def spectrum(self) -> npt.NDArray[np.float64]: ...
    def alpha_at_quantile(self, q: float) -> float: ...
    def suggest_scale(self, extraction: str = ..., coverage: Optional[float] = ...) -> float: ...
    def classify_facets(self, a: float) -> Dict[str, int]: ...
    def surface(
        self, a: Optional[float] = ..., extraction: str = ...
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], npt.NDArray[np.int64]]: ...

def vertex_curvatures(
    vertices: _Points,
    faces: npt.ArrayLike,
    *,
    rings: Optional[int] = ...,
    radius: Optional[float] = ...,
    estimator: str = ...,
) -> Layer: ...

class NoiseEstimate(float):
    spacing: float
    noise_24: float
    calls_for_denoising: bool

def estimate_noise(points: _Points) -> NoiseEstimate: ...
def denoise(points: _Points, neighbors: Optional[int] = ...) -> npt.NDArray[np.float64]: ...
def read_point_cloud(
    path: Union[str, os.PathLike],
    *,
    classes: Optional[Union[int, Sequence[int]]] = ...,
    drop_withheld: bool = ...,
    returns: str = ...,
) -> PointCloud: ...

from .matching import Matches as Matches
from .matching import Regions as Regions
from .matching import curvedness as curvedness
from .matching import farthest_point_sample as farthest_point_sample
from .matching import match_regions as match_regions
from .matching import region_descriptors as region_descriptors
from .matching import shape_index as shape_index
