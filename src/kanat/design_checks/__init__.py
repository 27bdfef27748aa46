"""Design checks of a mooring (``kanat design``, ``kanat.design(case)``): utilisation of every
line in intact and damaged conditions under API RP 2SK, and fatigue life (docs/design.md).

| module | |
|---|---|
| :mod:`.conditions` | the variants: a cable removed, a sea state and seed |
| :mod:`.factors` | required safety factors by standard, analysis and condition |
| :mod:`.records` | tension records of a run: fairlead, reference strengths |
| :mod:`.check` | the runs and the tables |
"""
from .check import FATIGUE_COLUMNS, UTILISATION_COLUMNS, DesignResult, design, write_tables

__all__ = ["DesignResult", "FATIGUE_COLUMNS", "UTILISATION_COLUMNS", "design", "write_tables"]
