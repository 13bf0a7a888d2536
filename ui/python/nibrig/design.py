"""A design's modes and the forcing model (Sec. 5), predicted designs (Sec. 5.3), their place in a space, the design searches (Sec. 6.2, 7), and the loop from a print back to its target."""

from ._core import design as _design

Designer = _design.Designer
Prediction = _design.Prediction
Search = _design.Search
Modes = _design.Modes
Forcing = _design.Forcing
designer = _design.designer
Calibration = _design.Calibration
calibrate_material = _design.calibrate_material
calibrate_surface = _design.calibrate_surface
CalibrationBar = _design.CalibrationBar
RingDownCalibration = _design.RingDownCalibration
calibration_bar = _design.calibration_bar
calibrate_ring_down = _design.calibrate_ring_down
DesignLoop = _design.DesignLoop
loop = _design.loop

__all__ = ["Designer", "Prediction", "Search", "Modes", "Forcing", "designer", "Calibration", "calibrate_material",
           "calibrate_surface", "CalibrationBar", "RingDownCalibration", "calibration_bar", "calibrate_ring_down",
           "DesignLoop", "loop"]
