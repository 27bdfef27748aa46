"""Design checks of a mooring (``kanat design``, ``kanat.design(case)``): utilisation of every
line in intact and damaged conditions under API RP 2SK or DNV-OS-E301, by dynamic runs, quasi-static
statics or tension spectra, and fatigue life (docs/design.md).

| module | |
|---|---|
| :mod:`.conditions` | the variants: a cable removed, a sea state and seed |
| :mod:`.factors` | required safety factors by standard, analysis and condition |
| :mod:`.records` | tension records of a run: fairlead, reference strengths |
| :mod:`.quasi_static` | the vessel's design offset and the statics there |
| :mod:`.spectral_check` | the check from a spectral analysis's tension spectra |
| :mod:`.check` | the runs and the tables |
"""
from .check import FATIGUE_COLUMNS, UTILISATION_COLUMNS, DesignResult, design, write_tables

__all__ = ["DesignResult", "FATIGUE_COLUMNS", "UTILISATION_COLUMNS", "design", "write_tables"]
