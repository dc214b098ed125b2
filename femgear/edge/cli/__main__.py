"""``python -m femgear.edge.cli``: the same as the ``femgear`` command."""

import sys

from femgear.edge.cli import main

sys.exit(main())
