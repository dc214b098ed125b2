"""Importing femgear has no side effects and pulls in neither gmsh, VTK nor matplotlib."""

import subprocess
import sys


def test_import_is_light():
    code = (
        "import sys, pkgutil, importlib, femgear\n"
        "for m in pkgutil.walk_packages(femgear.__path__, 'femgear.'):\n"
        "    if m.name.split('.')[-1] in ('__main__',) or m.name.startswith('femgear.physics.mesh'):\n"
        "        continue\n"
        "    importlib.import_module(m.name)\n"
        "heavy = [m for m in ('gmsh', 'vtk', 'pyvista', 'matplotlib') if m in sys.modules]\n"
        "print(','.join(heavy))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.strip()
    assert out == "", f"heavy modules imported at import time: {out}"
