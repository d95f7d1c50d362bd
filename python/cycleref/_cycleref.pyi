# The native module under the cycleref package: its raw tuples are made into
# the package's types by __init__.py; use the package, not this module.
import os
from typing import Any, Iterator, List, Mapping, Optional, Tuple, Union, final

__all__: List[str]

class Error(ValueError): ...

class ProgramError(Error):
    line: int
    word: Optional[str]
    rule: str

class CycleError(ProgramError): ...

@final
class MoveIter(Iterator[Tuple[Any, ...]]):
    def __next__(self) -> Tuple[Any, ...]: ...

_Source = Union[str, bytes, "os.PathLike[str]"]
_Path = Optional[Union[str, "os.PathLike[str]"]]

def expand(
    program: _Source,
    *,
    profile: str = "gsk988",
    increment: str = "is-b",
    inch: bool = False,
    radius: bool = False,
    params: _Path = None,
    readings: Optional[Mapping[str, str]] = None,
    engine: str = "impl",
    name: str = "<string>",
) -> Tuple[str, int, List[Tuple[Any, ...]]]: ...
def iter_moves(
    program: _Source,
    *,
    profile: str = "gsk988",
    increment: str = "is-b",
    inch: bool = False,
    radius: bool = False,
    params: _Path = None,
    readings: Optional[Mapping[str, str]] = None,
    engine: str = "impl",
    name: str = "<string>",
) -> MoveIter: ...
def check(
    program: _Source,
    trace: _Source,
    *,
    tolerance: int = 0,
    csv: bool = False,
    profile: str = "gsk988",
    increment: str = "is-b",
    inch: bool = False,
    radius: bool = False,
    params: _Path = None,
    readings: Optional[Mapping[str, str]] = None,
    engine: str = "impl",
    name: str = "<string>",
) -> Tuple[bool, int, str, str]: ...
def vector_case(seed: int, index: int) -> str: ...
