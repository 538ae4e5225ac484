"""``dyncalc spring-series`` and ``dyncalc spring-parallel``."""
from __future__ import annotations

import click

from .options import output_options

NETWORK_HELP = """
\b
Each ELEMENT is one of:
  200N/m, "3 kN*m/rad", inf         a stiffness (inf: a rigid link)
  "series(A, B, ...)"               elements in series, nested freely
  "parallel(A, B, ...)"             elements in parallel
  "cantilever(l=2m, EI=...)"        3 EI/l^3   (or E=... and I=...)
  "simply-supported(l=4m, EI=...)"  48 EI/l^3  at midspan
  "beam(c=..., l=..., EI=...)"      c EI/l^3   from any beam table
  "axial(l=..., EA=...)"            EA/l       (or E=... and A=...)
  "torsion-bar(l=..., GJ_t=...)"    G J_t/l    (or G=... and J_t=...), torsional
  "coil(G=..., d=..., D=..., n=...)"  G d^4/(8 D^3 n)
A word NAME=QUANTITY (E=200GPa, EI="2e4 N*m^2", l=1m) is a shared value that every
element needing NAME and not giving it takes. Linear and torsional elements cannot
be mixed. The result k_eq is in the unit the elements were typed in when they
share one, otherwise SI; element functions also report their own stiffness (k1, ...).
"""


def _network_command(how: str, summary: str, examples: str):
    @click.command(f"spring-{how}", help=f"{summary}\n{NETWORK_HELP}\n{examples}",
                   short_help=summary.split("\n")[0])
    @click.argument("elements", nargs=-1, metavar="ELEMENT...")
    @output_options
    def command(elements, out):
        if out.batch is not None:
            from ..batch import SpringRows

            return out.run_batch(SpringRows(how, strict=out.strict), {"": elements})
        from ..commands.springs import network_stiffness

        return out.emit(out.compute(
            lambda: network_stiffness(how, list(elements), strict=out.strict)))

    return command


spring_series = _network_command(
    "series",
    "Equivalent stiffness of springs in series: 1/k_eq = sum 1/k_i.",
    """\b
Examples:
  dyncalc spring-series "200 N/m" "300 N/m"                      # k_eq = 120 N/m
  dyncalc spring-series "parallel(cantilever(l=2m), cantilever(l=1m))" 5kN/m \\
      EI="2e4 N*m^2"                                   # E5.26, system 2
  dyncalc spring-series "beam(c=1, l=1m, EI=2e4N*m^2)" 5kN/m   # E5.19""")

spring_parallel = _network_command(
    "parallel",
    "Equivalent stiffness of springs in parallel: k_eq = sum k_i.",
    """\b
Examples:
  dyncalc spring-parallel "200 N/m" "300 N/m"                    # k_eq = 500 N/m
  dyncalc spring-parallel "simply-supported(l=2*1.5m)" \\
      "axial(l=(1+2**0.5)*1.5m)" EI="1e5 N*m^2" EA="2e7 N"        # E5.11
  dyncalc spring-parallel "cantilever(l=2m)" "cantilever(l=1m)" 5kN/m \\
      EI="2e4 N*m^2"                                   # E5.26, system 1""")

COMMANDS = [spring_series, spring_parallel]
