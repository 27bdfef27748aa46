"""The cases a design check runs: one per condition (intact, one cable removed), sea state and seed.

Every variant is a validated case built by :meth:`kanat.model.Case.replace` from the design
case, so it is checked as a case file would be; each is solved and run by the front door
(:mod:`kanat.api`), never by a model directly.
"""
from __future__ import annotations

import json
from dataclasses import dataclass

from kanat.errors import KanatError
from kanat.model import Case
from kanat.model.design import SeaState

INTACT = "intact"
DAMAGED = "damaged"


@dataclass(frozen=True)
class Condition:
    """A state of the mooring: all its lines, or one removed.

    Attributes
    ----------
    name : str
        ``intact`` or ``damaged:<cable>``.
    kind : {"intact", "damaged"}
    removed : str or None
        The cable removed.
    """

    name: str
    kind: str
    removed: str | None = None


def conditions(case: Case) -> list[Condition]:
    """The conditions ``case.design.conditions`` names, in order, each once.

    ``damaged`` stands for every cable removed in turn; a cable's name for that cable removed.
    """
    cables = [c.name for c in case.cables]
    found: list[Condition] = []
    for entry in case.design.conditions:
        if entry == INTACT:
            found.append(Condition(INTACT, INTACT))
        elif entry == DAMAGED:
            found += [Condition(f"{DAMAGED}:{name}", DAMAGED, name) for name in cables]
        elif entry in cables:
            found.append(Condition(f"{DAMAGED}:{entry}", DAMAGED, entry))
        else:
            raise KanatError(f"design.conditions: '{entry}' is neither 'intact', 'damaged' nor a "
                             f"cable of the case (cables: {', '.join(cables)})")
    unique = {c.name: c for c in found}
    return list(unique.values())


def without_cable(case: Case, cable: str) -> Case:
    """``case`` with one cable deleted (the rest as written), validated anew.

    Raises
    ------
    kanat.errors.CaseError
        When the remaining case is not a valid case (it had one cable only, say).
    """
    data = json.loads(case.model_dump_json(by_alias=True, exclude_unset=True))
    kept = [c for c in data["cables"] if c["name"] != cable]
    if len(kept) == len(data["cables"]):
        raise KanatError(f"the case has no cable '{cable}'")
    if not kept:
        raise KanatError(f"removing '{cable}' leaves no cable: the damaged condition needs a "
                         "mooring of two lines or more")
    changes = {"cables": kept}
    if case.design is not None:             # the variant is one condition; its own list would name the cable
        changes["design.conditions"] = ["intact"]
    return case.replace(changes)


def condition_case(case: Case, condition: Condition) -> Case:
    """The case of a condition (the design case itself when intact)."""
    return case if condition.removed is None else without_cable(case, condition.removed)


def wave_seed(case: Case, index: int) -> int:
    """Seed of the ``index``-th run of a sea state: the case's JONSWAP seed (0 if none) + index."""
    waves = case.environment.waves
    return getattr(waves, "seed", 0) + index


def sea_state_case(case: Case, sea_state: SeaState, seed: int) -> Case:
    """``case`` in one sea state: its waves the sea state's JONSWAP sea with ``seed``, its
    ``simulation.duration`` the sea state's ``duration``; the waves' ``ramp`` and
    ``stretching`` kept from the case."""
    waves = {"type": "jonswap", "hs": sea_state.hs, "tp": sea_state.tp, "gamma": sea_state.gamma,
             "heading_deg": sea_state.heading_deg, "seed": seed}
    written = case.environment.waves
    if written is not None:
        waves.update(ramp=written.ramp, stretching=written.stretching)
    return case.replace({"environment.waves": waves, "simulation.duration": sea_state.duration})
