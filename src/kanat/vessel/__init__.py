"""The vessel: manoeuvres (track kinematics) and pitch."""
