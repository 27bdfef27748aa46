"""Physical sanity checks of a validated case, with numbers and units.

Each check looks at one kind of mistake that a schema cannot see (a line heavier in
water than in air, an anchor under the seabed, a cable too short for its ends, a
time step that does not divide the output interval, ...) and reports it as an error
(the case cannot be run as written) or a warning (it can, but probably not as meant).

:func:`physical_checks` runs them all; :data:`LIMIT_CHECKS` and :data:`CHECKS` list them in
order. The checks live by area: :mod:`~kanat.model.line_checks` (lines, bodies, anchors),
:mod:`~kanat.model.sea_checks` (waves, tow, plane), :mod:`~kanat.model.problem_checks` (sphere,
pitch, ignored sections), :mod:`~kanat.model.run_checks` (numbers and work) and
:mod:`~kanat.model.setup_checks` (what the solvers set up); :mod:`~kanat.model.findings`
collects what they find.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING

from ..errors import Problem
from .findings import Findings
from .line_checks import (MAX_STATIC_STRAIN, MAX_STRETCH, check_anchors, check_attachments, check_bodies, check_clamps,
                          check_element_length, check_fixed_span, check_hanging_loads, check_line_types,
                          check_mooring_buoys, check_positions_above_seabed)
from .paths import Path
from .problem_checks import RESONANCE_GAIN, check_ignored_sections, check_pitch, check_sphere
from .run_checks import (TIME_TOL, check_discretization, check_magnitudes, check_pitch_size, check_run_length,
                         check_run_size, check_time_steps)
from .sea_checks import (BREAKING_DEPTH_RATIO, BREAKING_STEEPNESS, DEEP_WATER_KH, check_dimensions,
                         check_towing, check_waves, wavelength)
from .setup_checks import check_continuum_cable, check_lumped_network, check_scheme, check_sea, check_track
from .support import check_support

if TYPE_CHECKING:                 # a check takes a case, and the case's edit runs the checks (edit.py)
    from .case import Case

__all__ = ["BREAKING_DEPTH_RATIO", "BREAKING_STEEPNESS", "CHECKS", "DEEP_WATER_KH", "Findings", "LIMIT_CHECKS",
           "MAX_STATIC_STRAIN", "MAX_STRETCH", "RESONANCE_GAIN", "TIME_TOL", "physical_checks", "wavelength"]


LIMIT_CHECKS: tuple[Callable[[Case, Findings], None], ...] = (
    check_magnitudes, check_discretization, check_run_size, check_pitch_size,
)
"""Bounds on numbers and work (:mod:`kanat.model.limits`), in order: each assumes the
bounds of the ones before it, so the first that finds an error is the last to run, and the
sanity checks of :data:`CHECKS` (which assume numbers in range) are skipped."""


CHECKS: tuple[Callable[[Case, Findings], None], ...] = (
    check_line_types, check_bodies, check_anchors, check_positions_above_seabed, check_fixed_span, check_hanging_loads,
    check_mooring_buoys, check_time_steps, check_element_length, check_waves, check_towing,
    check_dimensions, check_sphere, check_pitch, check_attachments, check_clamps, check_ignored_sections,
    check_support, check_scheme, check_track, check_sea, check_continuum_cable, check_lumped_network,
    check_run_length,
)


def physical_checks(case: Case, file: str | None = None,
                    lines: Mapping[Path, int] | None = None,
                    max_output_bytes: float | str | None = None) -> list[Problem]:
    """Run every limit and sanity check on a validated case.

    Parameters
    ----------
    case : Case
        A case that passed validation.
    file : str or None
        Case file name for the problems.
    lines : mapping of key path to int, optional
        Lines of the case file's keys (:func:`kanat.io.yaml_loader.load_yaml`).
    max_output_bytes : float, str or None
        Largest estimated result of a dynamic run [bytes] (``"8G"`` works too); None:
        the environment variable ``KANAT_MAX_OUTPUT_BYTES``, else 2 GiB
        (:func:`kanat.model.limits.max_output_bytes`).

    Returns
    -------
    list of Problem
        Errors and warnings, in the order of :data:`LIMIT_CHECKS` then :data:`CHECKS`;
        only the first failing limit check's errors when one fails.
    """
    out = Findings(file, lines, max_output_bytes)
    for check in LIMIT_CHECKS:
        check(case, out)
        if out.problems:  # the limit checks report errors only; later ones assume them met
            return out.problems
    for check in CHECKS:
        check(case, out)
    return out.problems
