"""Catalog: rigid-body scenes with loads along a body (the ``rigid-body`` command;
../shared/SCENES.md "Rigid-body scenes"): bearing reactions and moments, stress resultants
``N``, ``V``, ``M`` at ``x=`` and ``t=``.

This module is one of :data:`dyncalc.scenes.kinetics.KINETICS_MODULES`: every scene it
registers is run by ``rigid-body --scene`` and by no other command. See
:mod:`dyncalc.scenes.kinetics` for how a scene joins the command (its ``kinds``, ``x``/``t``
as optional parameters, ``accepts_zeta=False``).
"""
from __future__ import annotations
