"""The source papers' studies, on top of the models: each returns data; pictures are in
:mod:`kanat.report`, the verbs in ``kanat study``.

| module | study |
|---|---|
| :mod:`.factorization` | Kaliukh & Vusatiuk 2018: full vs factorized schemes (accelerating vehicle, planar 80 m, spatial 100 m) |
| :mod:`.scheme_comparison` | Zhang, Zhang & Liu 2012: the generalized-α family against a fine reference on a turn |
| :mod:`.stability` | stability of a scheme over time steps (Courant ranges, Kaliukh & Vusatiuk 2018, section 4) |
| :mod:`.trawl` | Bezverkhyi 2006: the branched trawl's speed step, the paper's findings as checks |
| :mod:`.pitch` | Gaisha: frequency scans, moment surfaces, Fourier truncation |
| :mod:`.pitch_tow` | a tow from a pitching vessel, once per stabilizer mode |
"""
