"""Figures from results (matplotlib is imported inside the functions, never at import)."""

from __future__ import annotations

from pathlib import Path


def save_figure(fig, path: str | Path, dpi: int = 120) -> Path:
    """Lay out, save as PNG atomically (creating the folder, mode 0644) and close a figure."""
    import matplotlib.pyplot as plt

    from femgear.edge.io.atomic import atomic_write

    try:
        fig.tight_layout()
        with atomic_write(path, "wb") as fh:
            fig.savefig(fh, format="png", dpi=dpi)
    finally:
        plt.close(fig)
    return Path(path)
