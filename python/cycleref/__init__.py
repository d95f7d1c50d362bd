r"""cycleref: the CNC manuals' lathe thread and groove cycles (G76, G78, G32, G92, G75.1), exactly.

Expand a program into its moves, stream the moves of a large one, check a
vendor's toolpath against ours, and generate conformance vectors. Lengths
are :class:`decimal.Decimal` values with exactly the increment system's
decimals (never floats); a start angle is a :class:`fractions.Fraction` of
thousandths of a degree.

>>> import cycleref
>>> program = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\nG76 X60.64 Z-62 P3.680 Q1.800 F6\n"
>>> (cycle,) = cycleref.expand(program, profile="gsk988")
>>> cycle.code, cycle.line, len(cycle.moves)
('G76', 4, 30)
>>> cycle.moves[0]
Move(cycle='G76', line=4, motion='rapid', x=Decimal('64.400'), z=Decimal('8.961'), ...)

(The examples of the functions below use this ``program``, the M68x6
thread of the GSK 988TA manual, examples/gsk988-m68x6.nc.)

Every function takes the machine as the ``cycleref`` command does:
``profile`` (``"fanuc"``, ``"gsk980"``, ``"gsk988"``, ``"linuxcnc"``),
``increment`` (``"is-b"``, ``"is-c"``; ``None``, the default, is the
profile's own: IS-B, or IS-C on ``linuxcnc``), ``inch``, ``radius`` (X as a radius),
``params`` (the path of a parameter file, as ``--params``), ``readings``
(a mapping of reading ids to values, as ``--reading ID=VALUE``, e.g.
``readings={"R-RUNOUT": "gsk988-only"}``; ``cycleref readings`` lists
them, and an unknown id or value raises :class:`ValueError` naming the valid
ones) and ``engine``
(``"impl"``, the fixed-point engine, or ``"spec"``, the exact reference
model; both give the same moves). A program is its text (``str`` or
``bytes``) or the path of its file (:class:`os.PathLike`, read from disk a
line at a time); ``name`` is what messages call a program given as text.
"""

from __future__ import annotations

import json as _json
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from typing import Any, Dict, Iterator, List, Mapping, Optional, Tuple

from . import _cycleref
from ._cycleref import CycleError, Error, ProgramError
from ._cycleref import __version__

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


@dataclass(frozen=True)
class Pass:
    """The G76 pass a move belongs to, in the manual's terms.

    ``kind`` is ``"rough"``, ``"finish"`` or ``"single"`` (the one pass of a
    G92 block, depth and cut 0); ``number`` counts the passes of
    that kind from 1; ``start`` is the thread start (multi-start L);
    ``depth`` the total depth of cut and ``cut`` this pass's increment of
    it; ``flank`` the infeed side (``"right"``, ``"centre"``, ``"left"``;
    None in a :class:`Step` of a check report).
    """

    kind: str
    number: int
    start: int
    depth: Decimal
    cut: Decimal
    flank: Optional[str]


@dataclass(frozen=True)
class Plunge:
    """The G75.1 plunge a move belongs to: its layer and its number in the layer
    (``number`` is None on the move to a new layer)."""

    layer: int
    number: Optional[int]


@dataclass(frozen=True)
class Move:
    """One move of a cycle.

    ``cycle`` and ``line``: the cycle's G code (``"G76"``, ``"G32"``,
    ``"G75.1"``, ``"G92"``, ``"G78"``) and the line of the block that runs it. ``motion`` is
    ``"rapid"``, ``"feed"``, ``"thread"``, ``"arc-cw"`` or ``"arc-ccw"``;
    ``x``, ``z`` the end point (X in X-word units, diameter by default);
    ``centre`` the arc's absolute centre ``(x, z)`` (arcs only); ``role``
    what the move does in its pass (``"approach"``, ``"cut"``,
    ``"run-out"``, ``"peck"``, ...); ``lead`` the lead as programmed
    (``"F6.0"``, ``"I20.0"``, ``"K2.5"`` on the linuxcnc profile; thread
    moves only); ``start_angle_millidegrees`` and
    ``sync`` where the spindle synchronisation starts (thread moves only);
    ``pass_`` the G76 pass, ``plunge`` the G75.1 plunge.

    >>> m = cycleref.expand(program)[0].moves[1]
    >>> m.motion, m.end, m.lead, m.sync, m.pass_.depth
    ('thread', (Decimal('64.400'), Decimal('-59.000')), 'F6.0', True, Decimal('1.800'))
    """

    cycle: str
    line: int
    motion: str
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
    def end(self) -> Point:
        """The end point ``(x, z)``."""
        return (self.x, self.z)

    def __repr__(self) -> str:
        fields = ", ".join(f"{k}={getattr(self, k)!r}" for k in self.__dataclass_fields__)
        return f"Move({fields})"


@dataclass(frozen=True)
class Cycle:
    """A cycle of a program with its moves.

    ``code`` the G code; ``line`` the line of the block that runs it (G76 and
    G75.1: block 2); ``params_line`` the line of block 1 (None for G32, and
    for a G76 without block 1); ``from_`` the tool's position before a G75.1
    cycle (None otherwise); ``start`` the start point; ``unit`` (``"mm"`` or
    ``"inch"``) and ``decimals`` the units of its lengths.
    """

    code: str
    line: int
    params_line: Optional[int]
    from_: Optional[Point]
    start: Point
    unit: str
    decimals: int
    moves: List[Move]


def _move(t: tuple) -> Move:
    (code, line, motion, x, z, centre, role, lead, angle, sync, pass_, plunge) = t
    return Move(
        code,
        line,
        motion,
        x,
        z,
        centre,
        role,
        lead,
        angle,
        sync,
        Pass(*pass_) if pass_ is not None else None,
        Plunge(*plunge) if plunge is not None else None,
    )


def expand(
    program: Any,
    *,
    profile: str = "gsk988",
    increment: str | None = None,
    inch: bool = False,
    radius: bool = False,
    params: Any = None,
    readings: Mapping[str, str] | None = None,
    engine: str = "impl",
    name: str = "<string>",
) -> List[Cycle]:
    """The cycles of ``program`` with their moves, as ``cycleref expand`` prints them.

    The whole program is read and checked first; any error raises
    :class:`ProgramError` (a block the reader refuses) or
    :class:`CycleError` (a cycle's alarm) with the command's message and
    the error's ``line``, ``word`` and ``rule``. It holds every move, so a
    program whose expansion has more than 1 000 000 moves is refused with
    :class:`Error` before any is built: use :func:`iter_moves`, which
    streams them. Every cycle obeys the pass limit (reading R-BUDGET): a
    cycle of more pass paths than ``pass_limit`` raises :class:`CycleError`
    (``rule`` ``cycle:too_much_work``).

    >>> cycles = cycleref.expand(program, profile="gsk988")
    >>> [(c.code, c.line, len(c.moves)) for c in cycles]
    [('G76', 4, 30)]
    >>> cycles[0].moves[10].pass_
    Pass(kind='rough', number=3, start=1, depth=Decimal('3.118'), cut=Decimal('0.572'), flank='right')
    """
    unit, decimals, cycles = _cycleref.expand(
        program,
        profile=profile,
        increment=increment,
        inch=inch,
        radius=radius,
        params=params,
        readings=readings,
        engine=engine,
        name=name,
    )
    return [
        Cycle(code, line, params_line, from_, start, unit, decimals, [_move(m) for m in moves])
        for (code, line, params_line, from_, start, moves) in cycles
    ]


def iter_moves(
    program: Any,
    *,
    profile: str = "gsk988",
    increment: str | None = None,
    inch: bool = False,
    radius: bool = False,
    params: Any = None,
    readings: Mapping[str, str] | None = None,
    engine: str = "impl",
    name: str = "<string>",
) -> Iterator[Move]:
    """The moves of every cycle of ``program``, in order, computed as they are taken.

    Memory is the program (its text, or nothing for a file: it is read a
    line at a time) and one cycle's engine, whatever the number of moves.
    The whole program is checked when this is called, as the command does
    before it writes anything: errors are raised here, never half-way.

    >>> sum(1 for m in cycleref.iter_moves(program) if m.motion == "thread")
    12
    """
    native = _cycleref.iter_moves(
        program,
        profile=profile,
        increment=increment,
        inch=inch,
        radius=radius,
        params=params,
        readings=readings,
        engine=engine,
        name=name,
    )
    return map(_move, native)


@dataclass(frozen=True)
class Step:
    """A move of ours or of the trace in a divergence.

    ``motion``, ``x``, ``z``, ``centre`` (arcs), ``lead`` (threads) as in
    :class:`Move`; ``cycle`` the cycle's G code and line (None for a move of
    the program outside cycles, then ``line`` is its line); ``point`` the
    point in the manual's terms (``"Bn (pass start, ...)"``); ``pass_`` the
    G76 pass, ``plunge`` the G75.1 plunge.
    """

    motion: str
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
    """Where the trace parts from our toolpath.

    ``what`` names the divergence (``"rapid point"``, ``"end point"``,
    ``"missing pass"``, ...); ``moves`` how many moves it covers; ``ours`` and
    ``theirs`` the two moves (either is None for a missing or extra move);
    ``difference`` the difference of the end points in increments
    ``(x, z)`` (ours minus theirs), ``centre_difference`` that of the arc
    centres. ``cycle``, ``pass_`` and ``point`` are those of our move (else
    of theirs).
    """

    what: str
    moves: int
    ours: Optional[Step]
    theirs: Optional[Step]
    difference: Optional[Tuple[int, int]]
    centre_difference: Optional[Tuple[int, int]]

    @property
    def cycle(self) -> Optional[Tuple[str, int]]:
        """The cycle's G code and line."""
        s = self.ours or self.theirs
        return s.cycle if s else None

    @property
    def pass_(self) -> Optional[Pass]:
        """The G76 pass."""
        s = self.ours or self.theirs
        return s.pass_ if s else None

    @property
    def point(self) -> Optional[str]:
        """The point, in the manual's terms."""
        s = self.ours or self.theirs
        return s.point if s else None


@dataclass(frozen=True)
class Report:
    """The result of :func:`check`.

    ``agree`` is True when the toolpaths agree within the tolerance;
    ``divergence_count`` counts every divergence, ``divergences`` lists the
    first 10 000; ``text`` is the command's text report and ``json`` its
    ``cycleref-check/1`` document (as a dict).
    """

    agree: bool
    divergence_count: int
    divergences: List[Divergence]
    tolerance: int
    text: str
    json: Dict[str, Any]

    def __bool__(self) -> bool:
        return self.agree

    def __str__(self) -> str:
        return self.text


def _point(p: Optional[Dict[str, str]]) -> Optional[Point]:
    return None if p is None else (Decimal(p["x"]), Decimal(p["z"]))


def _step(s: Optional[Dict[str, Any]]) -> Optional[Step]:
    if s is None:
        return None
    p = s.get("pass")
    pl = s.get("plunge")
    c = s.get("cycle")
    return Step(
        motion=s["motion"],
        x=Decimal(s["x"]),
        z=Decimal(s["z"]),
        centre=_point(s.get("centre")),
        lead=s.get("lead"),
        cycle=(c["code"], c["line"]) if c else None,
        line=c["line"] if c else s.get("line"),
        point=s.get("point"),
        role=s.get("role"),
        pass_=Pass(p["kind"], p["number"], p["start"], Decimal(p["depth"]), Decimal(p["cut"]), p.get("flank"))
        if p
        else None,
        plunge=Plunge(pl["layer"], pl.get("number")) if pl else None,
    )


def _pair(d: Optional[Dict[str, int]]) -> Optional[Tuple[int, int]]:
    return None if d is None else (d["x"], d["z"])


def check(
    program: Any,
    trace: Any,
    *,
    tolerance: int = 0,
    csv: bool = False,
    profile: str = "gsk988",
    increment: str | None = None,
    inch: bool = False,
    radius: bool = False,
    params: Any = None,
    readings: Mapping[str, str] | None = None,
    engine: str = "impl",
    name: str = "<string>",
) -> Report:
    r"""Compares a vendor's toolpath (``trace``) with ours for ``program``, as ``cycleref check``.

    ``trace`` is an expanded program (plain G00/G01/G02/G03/G32 blocks) or
    a CSV (the README's columns): as text (``str`` or ``bytes``; a CSV when
    ``csv=True``) or as a path (read a line at a time; a CSV when its name
    ends in ``.csv``, as the command decides). ``tolerance`` is in increments and
    applies to coordinates only. An error of the program raises
    :class:`ProgramError` / :class:`CycleError`; an error of the trace
    raises :class:`Error` naming its line.

    A trace written from our moves, with rough pass 3 cut 0.036 too shallow:

    >>> (cycle,) = cycleref.expand(program)
    >>> blocks = [f"{'G32' if m.lead else 'G00'} X{m.x} Z{m.z} {m.lead or ''}" for m in cycle.moves]
    >>> trace = "G00 X80 Z10\n" + "\n".join(blocks).replace("X61.764", "X61.800")
    >>> report = cycleref.check(program, trace)
    >>> report.agree, report.divergences[0].what, report.divergences[0].difference
    (False, 'rapid point', (36, 0))
    >>> report.divergences[0].pass_.number, report.divergences[0].point
    (3, 'Bn (pass start, or An before a lead-in)')
    >>> cycleref.check(program, trace, tolerance=36).agree
    True
    """
    agree, count, text, doc = _cycleref.check(
        program,
        trace,
        tolerance=tolerance,
        csv=csv,
        profile=profile,
        increment=increment,
        inch=inch,
        radius=radius,
        params=params,
        readings=readings,
        engine=engine,
        name=name,
    )
    parsed = _json.loads(doc)
    divergences = [
        Divergence(
            what=d["what"],
            moves=d["moves"],
            ours=_step(d.get("ours")),
            theirs=_step(d.get("theirs")),
            difference=_pair(d.get("difference_increments")),
            centre_difference=_pair(d.get("centre_difference_increments")),
        )
        for d in parsed["divergences"]
    ]
    return Report(agree, count, divergences, tolerance, text, parsed)


def vectors(count: int, seed: int) -> Iterator[Dict[str, Any]]:
    """The conformance vectors ``cycleref vectors --count COUNT --seed SEED`` writes, one case at a time.

    Each case is the dict of its ``case-NNNN.json`` file (schema
    ``cycleref-vector/1``, see vectors/README.md): the program, the machine,
    and the expected moves or error.

    >>> case = next(cycleref.vectors(1, 1))
    >>> case["id"], case["schema"]
    ('case-0001', 'cycleref-vector/1')
    """
    for index in range(1, count + 1):
        yield _json.loads(_cycleref.vector_case(seed, index))
