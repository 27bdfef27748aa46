"""The source papers' studies, on top of the models: each returns data; pictures are in
:mod:`kanat.report`, the verbs in ``kanat study``.

| module | study |
|---|---|
| :mod:`.seed000` | seed 000: full vs factorized schemes (accelerating vehicle, planar 80 m, spatial 100 m) |
| :mod:`.seed002` | seed 002: the generalized-α family against a fine reference on a turn |
| :mod:`.stability` | stability of a scheme over time steps (Courant ranges, seed 000 section 4) |
| :mod:`.seed004` | seed 004: the branched trawl's speed step, the paper's findings as checks |
| :mod:`.pitch` | seed 003: frequency scans, moment surfaces, Fourier truncation |
| :mod:`.pitch_tow` | a tow from a pitching vessel, once per stabilizer mode |
"""
