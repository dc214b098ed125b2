"""Results files: JSON written atomically (a file is either complete or absent)."""

from femgear.io.results import to_plain, write_json

__all__ = ["to_plain", "write_json"]
