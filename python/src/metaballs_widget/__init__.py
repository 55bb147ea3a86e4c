"""Merging spheres drawn with marching cubes, as a notebook widget: ``Metaballs(spheres=2, iso=1)``."""

from ._widget import Metaballs

__all__ = ["Metaballs"]
