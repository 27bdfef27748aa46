"""The tow vessel: manoeuvres (:mod:`~kanat.vessel.track`) and pitch with the reactive stabilizer
(:mod:`~kanat.vessel.pitch`, seed 003, SPEC §6.2).

The pitch solvers are a sub-package of their own: code needing only the track does not load
them and their optimizers.
"""
