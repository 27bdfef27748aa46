"""The tow vessel: manoeuvres (:mod:`~kanat.vessel.track`) and pitch with the reactive stabilizer
(:mod:`~kanat.vessel.pitch`, Gaisha, theory/vessel.md §2).

The pitch solvers are a sub-package of their own: code needing only the track does not load
them and their optimizers.
"""
