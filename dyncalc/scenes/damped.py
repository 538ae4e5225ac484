"""Catalog: damped scenes (see SCENES.md)."""
