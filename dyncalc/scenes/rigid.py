"""Catalog: rigid scenes (see SCENES.md)."""
