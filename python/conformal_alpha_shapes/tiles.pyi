import os
from typing import Any, Dict, List, Optional, Sequence, Union

from distributed import Client
from distributed.security import Security

_Item = Union[str, float, int]

AUTOMATIC_RADIUS_SPACINGS: float
FRONT_REACH_SPACINGS: float

class TileError(ValueError): ...

def halo_spacings(radii: Sequence[_Item], rings: Sequence[int], spacing: float) -> float: ...
def process_tiles(
    input: Union[str, os.PathLike],
    output: Union[str, os.PathLike],
    *,
    tile_points: int = ...,
    workers: Optional[int] = ...,
    scheduler: Optional[str] = ...,
    security: Optional[Security] = ...,
    client: Optional[Client] = ...,
    merge: bool = ...,
    scales: Union[_Item, Sequence[_Item]] = ...,
    radii: Union[_Item, Sequence[_Item]] = ...,
    rings: Union[int, Sequence[int]] = ...,
    estimator: str = ...,
    denoise: Union[str, bool] = ...,
    denoise_neighbors: Optional[int] = ...,
    extraction: str = ...,
    halo: Optional[float] = ...,
    threads: int = ...,
    quiet: bool = ...,
    classes: Optional[Union[int, Sequence[int]]] = ...,
    drop_withheld: bool = ...,
    returns: str = ...,
    las: bool = ...,
) -> Dict[str, Any]: ...
def format_summary(summary: Dict[str, Any]) -> str: ...
def main(argv: Optional[List[str]] = ...) -> int: ...
