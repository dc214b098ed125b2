"""PNG files of the figures drawn by :mod:`femgear.edge.plot`, written atomically."""

from __future__ import annotations

from pathlib import Path

from femgear.edge.io.atomic import atomic_write


def save_figure(fig, path: str | Path, dpi: int = 120) -> Path:
    """Lay out, save as PNG atomically (creating the folder, mode 0644) and close a figure; returns the path."""
    import matplotlib.pyplot as plt

    try:
        fig.tight_layout()
        with atomic_write(path, "wb") as fh:
            fig.savefig(fh, format="png", dpi=dpi)
    finally:
        plt.close(fig)
    return Path(path)


__all__ = ["save_figure"]
