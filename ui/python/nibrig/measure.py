"""Recordings to friction, velocity-binned spectra and perceptual descriptors (Sec. 3, 4.4); catalogs."""

from ._core import measure as _measure

Measurement = _measure.Measurement
Catalog = _measure.Catalog
recording = _measure.recording
catalog = _measure.catalog
load_catalog = _measure.load_catalog
bundled_catalog = _measure.bundled_catalog

__all__ = ["Measurement", "Catalog", "recording", "catalog", "load_catalog", "bundled_catalog"]
