"""The continuum cable model (SPEC §2): box method in space, generalized-α family in time."""
