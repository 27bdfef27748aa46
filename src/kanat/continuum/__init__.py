"""The continuum cable model (theory/continuum.md): box method in space, generalized-α family in time.

A test-only oracle (an independent twin of compiled kernels that only the tests import) is a
module ``oracle_<method><dim>.py`` in the package whose kernels it checks, ``<method>`` saying how
it is written (``complex_step``, ``numpy``, ``sympy``) and ``<dim>`` the ``2d``/``3d`` of those
kernels where the package has both: here :mod:`.oracle_complex_step2d`, :mod:`.oracle_complex_step3d`,
:mod:`.oracle_numpy2d` and :mod:`.oracle_sympy3d`.
"""
