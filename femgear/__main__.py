"""``python -m femgear``: the same as the ``femgear`` command."""

import sys

from femgear.edge.cli import main

sys.exit(main())
