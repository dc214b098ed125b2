"""gmsh → skfem meshes with named boundaries (the only place gmsh is imported, lazily).

- ``section``  transverse gear sections (N teeth or the whole gear, exact involute and
               rack-generated trochoidal fillet, down to the bore) and annuli.
- ``housing``  a parametric gearbox housing (walls, bosses with the bearing seats, feet) around the pair.
"""
