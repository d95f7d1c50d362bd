# Type stubs of the cycleref package (the implementation is __init__.py over
# the native module _cycleref; the docstrings are there).
import os
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from typing import Any, Dict, Iterator, List, Literal, Mapping, Optional, Tuple, Union

__all__ = [
    "Cycle",
    "CycleError",
    "Divergence",
    "Error",
    "Move",
    "Pass",
    "Plunge",
    "ProgramError",
    "Report",
    "Step",
    "check",
    "expand",
    "iter_moves",
    "vectors",
]

Point = Tuple[Decimal, Decimal]
_ProgramSource = Union[str, bytes, "os.PathLike[str]"]
_ProfileName = Literal["fanuc", "gsk980", "gsk988", "linuxcnc"]
_IncrementName = Literal["is-b", "is-c"]
_EngineName = Literal["impl", "spec"]
_MotionName = Literal["rapid", "feed", "thread", "arc-cw", "arc-ccw"]

class Error(ValueError):
    """A program or trace that cycleref refuses."""

class ProgramError(Error):
    """The program reader refused a block."""

    line: int
    word: Optional[str]
    rule: str

class CycleError(ProgramError):
    """A cycle raised its alarm (``rule`` is ``cycle:NAME``)."""

@dataclass(frozen=True)
class Pass:
    kind: Literal["rough", "finish", "single"]
    number: int
    start: int
    depth: Decimal
    cut: Decimal
    flank: Optional[Literal["right", "centre", "left"]]

@dataclass(frozen=True)
class Plunge:
    layer: int
    number: Optional[int]

@dataclass(frozen=True)
class Move:
    cycle: Literal["G76", "G78", "G32", "G33", "G75.1", "G92"]
    line: int
    motion: _MotionName
    x: Decimal
    z: Decimal
    centre: Optional[Point]
    role: str
    lead: Optional[str]
    start_angle_millidegrees: Optional[Fraction]
    sync: Optional[bool]
    pass_: Optional[Pass]
    plunge: Optional[Plunge]
    @property
    def end(self) -> Point: ...

@dataclass(frozen=True)
class Cycle:
    code: Literal["G76", "G78", "G32", "G33", "G75.1", "G92"]
    line: int
    params_line: Optional[int]
    from_: Optional[Point]
    start: Point
    unit: Literal["mm", "inch"]
    decimals: int
    moves: List[Move]

@dataclass(frozen=True)
class Step:
    motion: _MotionName
    x: Decimal
    z: Decimal
    centre: Optional[Point]
    lead: Optional[str]
    cycle: Optional[Tuple[str, int]]
    line: Optional[int]
    point: Optional[str]
    role: Optional[str]
    pass_: Optional[Pass]
    plunge: Optional[Plunge]

@dataclass(frozen=True)
class Divergence:
    what: str
    moves: int
    ours: Optional[Step]
    theirs: Optional[Step]
    difference: Optional[Tuple[int, int]]
    centre_difference: Optional[Tuple[int, int]]
    @property
    def cycle(self) -> Optional[Tuple[str, int]]: ...
    @property
    def pass_(self) -> Optional[Pass]: ...
    @property
    def point(self) -> Optional[str]: ...

@dataclass(frozen=True)
class Report:
    agree: bool
    divergence_count: int
    divergences: List[Divergence]
    tolerance: int
    text: str
    json: Dict[str, Any]
    def __bool__(self) -> bool: ...

def expand(
    program: _ProgramSource,
    *,
    profile: _ProfileName = "gsk988",
    increment: _IncrementName | None = None,
    inch: bool = False,
    radius: bool = False,
    params: Optional[Union[str, "os.PathLike[str]"]] = None,
    readings: Optional[Mapping[str, str]] = None,
    engine: _EngineName = "impl",
    name: str = "<string>",
) -> List[Cycle]: ...
def iter_moves(
    program: _ProgramSource,
    *,
    profile: _ProfileName = "gsk988",
    increment: _IncrementName | None = None,
    inch: bool = False,
    radius: bool = False,
    params: Optional[Union[str, "os.PathLike[str]"]] = None,
    readings: Optional[Mapping[str, str]] = None,
    engine: _EngineName = "impl",
    name: str = "<string>",
) -> Iterator[Move]: ...
def check(
    program: _ProgramSource,
    trace: _ProgramSource,
    *,
    tolerance: int = 0,
    csv: bool = False,
    profile: _ProfileName = "gsk988",
    increment: _IncrementName | None = None,
    inch: bool = False,
    radius: bool = False,
    params: Optional[Union[str, "os.PathLike[str]"]] = None,
    readings: Optional[Mapping[str, str]] = None,
    engine: _EngineName = "impl",
    name: str = "<string>",
) -> Report: ...
def vectors(count: int, seed: int) -> Iterator[Dict[str, Any]]: ...
