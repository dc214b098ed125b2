"""Figures from results (matplotlib is imported inside the functions, never at import)."""
