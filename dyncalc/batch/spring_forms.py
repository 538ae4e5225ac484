"""The standard spring elements as products of powers of their parameters, which the batch
columns of ``spring-series``/``spring-parallel`` evaluate (:mod:`dyncalc.batch.fast_springs`,
:mod:`dyncalc.batch.fast_spring_trees`)."""
from __future__ import annotations

__all__ = ["ELEMENT_FORMS"]

#: The elements taken on columns: (coefficient, its leading factors, the alternative groups of
#: factors with their powers, the other factors with their powers), in the physics
#: function's order (:mod:`dyncalc.physics.springs`: ``_rigidity`` first, then ``l``).
#: ``beam``'s ``c`` is ``monomial``'s coefficient: a coefficient of 1 times ``c`` as the
#: first factor is the same mantissa and exponent at every step.
ELEMENT_FORMS = {
    "cantilever": (3.0, (), ((("EI", 1),), (("E", 1), ("I", 1))), (("l", -3),)),
    "simply-supported": (48.0, (), ((("EI", 1),), (("E", 1), ("I", 1))), (("l", -3),)),
    "beam": (1.0, (("c", 1),), ((("EI", 1),), (("E", 1), ("I", 1))), (("l", -3),)),
    "axial": (1.0, (), ((("EA", 1),), (("E", 1), ("A", 1))), (("l", -1),)),
    "torsion-bar": (1.0, (), ((("GJ_t", 1),), (("G", 1), ("J_t", 1))), (("l", -1),)),
    "coil": (0.125, (), (), (("G", 1), ("d", 4), ("D", -3), ("n", -1))),
}
