"""Catalog: rotating scenes (see SCENES.md)."""
