"""Type stubs of c2f._c2f, the compiled core (pybind11)."""

from typing import Any, Callable, Dict, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

class Term:
    """A pairwise cost of two labels, shared by edges and scaled by each edge's weight."""

    @staticmethod
    def potts() -> Term:
        """cost(a, b) = 0 if a == b else 1."""
    @staticmethod
    def truncated_linear(truncation: float) -> Term:
        """cost(a, b) = min(|a - b|, truncation); truncation > 0."""
    @staticmethod
    def truncated_quadratic(truncation: float, num_labels: int) -> Term:
        """cost(a, b) = min((a - b)^2, truncation), as a num_labels x num_labels table."""
    @staticmethod
    def table(costs: npt.ArrayLike) -> Term:
        """cost(a, b) = costs[a, b] for a float (L, L) array of finite costs."""
    @property
    def kind(self) -> str:
        """'potts', 'truncated_linear', 'tsgo_step' or 'table'."""
    @property
    def truncation(self) -> float:
        """The truncation of a truncated-linear term (0 otherwise)."""
    def cost(self, a: int, b: int) -> float:
        """The cost of labels a and b."""

class Energy:
    """E(x) = sum_v unary[v, x_v] + sum_e weight_e * term(x_u, x_v)."""

    def __init__(
        self,
        unary: npt.ArrayLike,
        edges: Optional[npt.ArrayLike] = None,
        weights: Optional[npt.ArrayLike] = None,
        term: Term = ...,
    ) -> None:
        """A general energy: unary (N, L) float costs, edges (E, 2) integer variable pairs,
        weights (E,) (default 1), one pairwise term on every edge."""
    @staticmethod
    def grid(
        unary: npt.ArrayLike,
        term: Term = ...,
        weight: Union[float, npt.ArrayLike] = 1.0,
        connectivity: int = 4,
    ) -> Energy:
        """A grid energy from unary (H, W, L) float costs (float32 kept in single precision);
        `term` on the edges to the right and down neighbours (and down-right, down-left when
        connectivity is 8), of weight `weight`: a number, or an array of shape
        (H, W, connectivity / 2) whose [y, x, k] weighs the edge to the k-th neighbour of
        (y, x). Labelings come back as (H, W)."""
    @staticmethod
    def read_uai(path: str, memory: Optional[float] = None) -> Energy:
        """A pairwise MARKOV model in the UAI format (energy = -ln potential). The path must be a
        regular file; `memory` is the budget in GiB (None: the default) that the file and the costs
        its declarations imply must fit before they are read (ValueError naming the file)."""
    def write_uai(self, path: str) -> None:
        """Writes the energy as a UAI MARKOV model (potentials exp(-cost), scaled per factor)."""
    def evaluate(self, labeling: npt.ArrayLike) -> float:
        """E(labeling) for a labeling of shape (N,) or the grid's (H, W)."""
    @property
    def num_variables(self) -> int: ...
    @property
    def num_labels(self) -> int: ...
    @property
    def num_edges(self) -> int: ...
    @property
    def shape(self) -> Optional[Tuple[int, int]]:
        """(H, W) for a grid energy, None for a general one."""
    @property
    def unary(self) -> npt.NDArray[np.float64]:
        """A copy of the unary costs, (N, L)."""
    @property
    def edges(self) -> npt.NDArray[np.int64]:
        """A copy of the edges' variable pairs, (E, 2)."""
    @property
    def weights(self) -> npt.NDArray[np.float64]:
        """A copy of the edges' weights, (E,)."""

def _defaults(name: str) -> Dict[str, Any]:
    """The library's RunDefaults named 'pairwise' or 'stereo', as a dict."""

def _solve(
    energy: Energy,
    schedule: Optional[Union[str, Sequence[npt.ArrayLike]]],
    *,
    defaults: str,
    method: str,
    options: Optional[Dict[str, Any]],
    time_limit: Optional[float],
    max_steps: Optional[int],
    plateau: Union[None, int, str],
    plateau_tolerance: Optional[float],
    start: Union[str, npt.ArrayLike],
    callback: Optional[Callable[[Dict[str, Any]], Optional[bool]]],
    memory: Optional[float],
    graph_memory: Optional[float],
) -> Dict[str, Any]:
    """The engine of c2f.solve (which documents the arguments); returns a dict."""

def read_image(path: str) -> npt.NDArray[np.uint8]:
    """An image file as an (H, W, 3) uint8 RGB array (grey is made colour)."""

def read_stereo_pair(left: str, right: str, gt: str = "", gt_divisor: float = 0.0,
                     mask: str = "", downscale: int = 1) -> Dict[str, Optional[np.ndarray]]:
    """A stereo pair loaded as c2f-stereo loads it: 'left', 'right' (RGB uint8), 'gt' ((H, W)
    float32 disparities, NaN unknown; None without a GT file), 'mask' ((H, W) bool, True =
    non-occluded; None without one), all shrunk by `downscale`."""

def stereo_energy(left: npt.ArrayLike, right: npt.ArrayLike, labels: int = 85,
                  smoothness: str = "tsgo_step", truncation: float = 2.0,
                  threads: int = 0, memory: Optional[float] = None) -> Energy:
    """The TSGO stereo energy of two RGB uint8 views (H, W, 3): disparities 0..labels-1 of the
    left view on a 4-connected grid; its schedules include the stereo presets and slic:S.
    threads: cores preparing the data (0: all); the energy is the same for every count.
    memory: the budget in GiB the preparation must fit (None: the machine's default)."""

def bad_pixel_rates(disparity: npt.ArrayLike, gt: npt.ArrayLike,
                    mask: Optional[npt.ArrayLike] = None) -> Dict[str, Any]:
    """Fractions of pixels with |disparity - gt| above 0.5, 1 and 2 over pixels of known GT
    ('all') and over the mask's pixels ('nonoccluded', None without a mask), and the pixel
    counts. A GT with no known pixel, or a mask marking none, is a ValueError."""

def read_segmentation(image: str, seeds: str, gt: str = "", convention: str = "colours",
                      downscale: int = 1) -> Dict[str, Optional[np.ndarray]]:
    """A segmentation scene loaded as c2f-segment loads it: 'image' (RGB uint8), 'seeds'
    ((H, W) int32, -1 where no seed), 'truth' ((H, W) int32, -1 unscored; None without GT),
    'palette' ((L, 3) RGB colour of each label)."""

def _segment(image: npt.ArrayLike, seeds: npt.ArrayLike, schedule: str, *, method: str,
             options: Optional[Dict[str, Any]], lambda_: float, theta: float, alpha: float,
             classes: int, kmeans: str, gmm_seed: int, edge_seed: int, threads: int,
             time_limit: Optional[float], max_steps: Optional[int],
             plateau: Union[None, str, int],
             callback: Optional[Callable[[Dict[str, Any]], Optional[bool]]],
             memory: Optional[float]) -> Dict[str, Any]:
    """The engine of c2f.segment (which documents the arguments); returns a dict."""

def partition(energy: Energy, level: str) -> npt.NDArray[np.int32]:
    """One level's partition of the energy's variables as group ids in the energy's shape:
    'cp:N_L,N_iter', 'local:..', 'threshold:T', 'agg:R', 'blocks:S', 'slic:S', any with '/cc'."""

def reduce(energy: Energy, partition: npt.ArrayLike) -> Energy:
    """The reduced energy over the groups of `partition` (group ids of every variable):
    reduce(e, p).evaluate(y) == e.evaluate(expand(y, p, L)) up to rounding."""

def expand(labeling: npt.ArrayLike, partition: npt.ArrayLike, num_labels: int) -> npt.NDArray[np.int32]:
    """The labeling of the variables in which every member of group g gets labeling[g]."""

def transfer(labeling: npt.ArrayLike, from_partition: npt.ArrayLike, to_partition: npt.ArrayLike,
             num_labels: int) -> npt.NDArray[np.int32]:
    """The same labeling of the variables, on the groups of `to_partition` (which refines
    `from_partition`)."""
