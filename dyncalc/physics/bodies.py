"""Round bodies and their shape factor ``kappa = J_C / (m r^2)`` (docs/scenes.md notation).

Shared by the rolling scenes and the ``rolling-onset`` command.
"""

#: Shape factor of each named body: thin shells and hoops carry all their mass at the radius.
KAPPA = {"solid-sphere": 0.4, "hollow-sphere": 2 / 3, "solid-cylinder": 0.5,
         "hollow-cylinder": 1.0, "hoop": 1.0}
