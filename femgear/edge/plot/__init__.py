"""Figures from results: each function draws one matplotlib figure and returns it (matplotlib is imported inside
the functions, never at import); :func:`femgear.edge.io.figures.save_figure` writes it.

- ``path``, ``rating``, ``coupled``  the fields along the path of contact, the ISO ratings, the coupling history
- ``dynamics``  time histories, mesh force, phase planes, spectra, sweeps of a dynamic response
- ``ltca``      loaded TE curves, harmonics, Harris map, load over the flank
- ``ehl``       the centre line of an EHL solution
"""


def pyplot():
    """``matplotlib.pyplot`` on the non-interactive Agg back-end, imported on the first figure (never at import)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt
