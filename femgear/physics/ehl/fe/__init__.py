"""EHL by finite elements and Newton–Krylov: Q1/P1 element tables (``stencil``), the stabilised
Galerkin Reynolds operator (``reynolds``), one discretisation level (``level``), dense Newton and
Newton–Krylov with a multilevel preconditioner (``newton``, ``krylov``), the nested point solve
(``point``) and the line contact (``line``)."""
