"""``python -m femgear``: the same as the ``femgear`` command."""

import sys

from femgear.cli import main

sys.exit(main())
