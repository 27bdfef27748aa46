"""Loads and laws: drag, weight, constitutive laws, flow fields."""
