"""``python -m kinematics`` runs the ``assur`` command line."""

import sys

from .cli import main

sys.exit(main())
