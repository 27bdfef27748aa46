"""The problem as validated data: line types, cables, bodies, environment, vessel.

Every class is a frozen pydantic model whose field names are the keys of the YAML
case format (``docs/reference/case-format.md``); read case files with
:func:`kanat.io.case_file.load_case`.
"""
from .cable import Attachment, Cable, CableEnd, CableSection, EndFixity
from .case import Case
from .components import Body, ElasticLaw, LineType, Point, SurfaceBuoy
from .environment import ComponentWaves, Current, Environment, JonswapWaves, RegularWaves, Seabed, Waves
from .operations import HarmonicMotion, VesselMotion, WinchStep
from .problems import (
                       PitchModel,
                       SphereDimensional,
                       SphereDimensionless,
                       SphereTwoCables,
                       Stabilizer,
)
from .simulation import Simulation
from .vessel import (
                       KNOT,
                       SEGMENT_TYPES,
                       Accelerate,
                       Heading,
                       SpeedStep,
                       Straight,
                       TrackSegment,
                       Turn,
                       Vessel,
                       VesselPitch,
)

__all__ = [
    "Accelerate", "Attachment", "Body", "Cable", "CableEnd", "CableSection", "Case", "Current",
    "ComponentWaves", "ElasticLaw", "EndFixity", "Environment", "HarmonicMotion", "Heading", "JonswapWaves", "KNOT",
    "LineType", "PitchModel", "Point", "RegularWaves", "SEGMENT_TYPES", "Seabed", "Simulation", "SpeedStep",
    "SphereDimensional", "SphereDimensionless", "SphereTwoCables", "SurfaceBuoy", "Stabilizer",
    "Straight", "TrackSegment", "Turn", "Vessel", "VesselMotion", "VesselPitch", "Waves", "WinchStep",
]
