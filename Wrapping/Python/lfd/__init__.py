"""LightField Deform: interactive deformation of light fields, on VTK.

Every public class of the C++ modules is available here::

    import lfd
    source = lfd.vtkLightFieldReader()
"""

from .lfdCore import *  # noqa: F401,F403
from .lfdIO import *  # noqa: F401,F403
from .lfdSynthesis import *  # noqa: F401,F403
from .lfdSegmentation import *  # noqa: F401,F403
from .lfdCalibration import *  # noqa: F401,F403
from .lfdDeformation import *  # noqa: F401,F403
from .lfdRendering import *  # noqa: F401,F403
from .lfdEvaluation import *  # noqa: F401,F403
from .lfdScene import *  # noqa: F401,F403
from .lfdWidgets import *  # noqa: F401,F403
from .lfdAcquisition import *  # noqa: F401,F403
