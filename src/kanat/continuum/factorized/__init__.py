"""Kaliukh & Vusatiuk's factorized and wave-factorized schemes for the continuum cable (theory/time-schemes.md §2–3).

| module | what |
|---|---|
| :mod:`.schemes` | the five registered schemes (``factorized``, ``factorized-4``, ``wave-factorized`` and its 2- and 3-block spatial splits) |
| :mod:`.system` | the equations as ``Y_t + B Y_s = D`` and what one step needs of the model (:class:`~.system.World`) |
| :mod:`.characteristics` | the split of ``B`` by propagation direction and wave type, and the ends through the characteristics |
| :mod:`.sweeps` | the factorized step (two or four implicit upwind sweeps); :mod:`.sweeps_compiled` its compiled twin |
| :mod:`.waves` | the wave-factorized step (gamma-weighted box sub-steps per wave block); :mod:`.waves_compiled` its compiled assembly |
| :mod:`.dense` | the small dense LU and the upwind sweep shared by both |
"""
