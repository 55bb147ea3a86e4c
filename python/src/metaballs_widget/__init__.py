"""Merging spheres drawn with marching cubes, as a notebook widget: ``Metaballs(spheres=2, iso=1)``."""

from ._widget import Metaballs, Metaballs2d

__all__ = ["Metaballs", "Metaballs2d"]
