"""The edge: files (``io``), figures (``plot``), the command line (``cli``) and
sweeps (``sweep``). It reads typed results and computes no physics."""
