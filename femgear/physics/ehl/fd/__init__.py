"""EHL by finite differences and nonlinear multigrid (Venner & Lubrecht 2000): the FD operator
and grid transfers (``operator``), zebra line relaxation (``relax``), the coarsest grid's dense
Newton (``newton``), outlet-spike elimination (``eliminate``), FAS / FMG cycles (``fas``) and the
point driver (``point``, ``method='fas'`` of :func:`femgear.physics.ehl.point.solve_point`)."""
