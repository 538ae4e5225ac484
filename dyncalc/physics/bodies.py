"""Round bodies and their shape factor ``kappa = J_C / (m r^2)`` (docs/scenes.md notation).

Shared by the rolling scenes and the ``rolling-onset`` command.
"""

from .inertia import AXIAL_FACTOR

#: Shape factor of each named body: thin shells and hoops carry all their mass at the radius
#: (a hollow cylinder here is a thin tube, the ring's factor), from
#: :data:`dyncalc.physics.inertia.AXIAL_FACTOR`.
KAPPA = {"solid-sphere": float(AXIAL_FACTOR["solid-sphere"]),
         "hollow-sphere": float(AXIAL_FACTOR["hollow-sphere"]),
         "solid-cylinder": float(AXIAL_FACTOR["solid-cylinder"]),
         "hollow-cylinder": float(AXIAL_FACTOR["ring"]), "hoop": float(AXIAL_FACTOR["ring"])}
