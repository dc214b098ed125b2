"""The system: the gear-rotor dynamics model (``dynamics``) and the bidirectional
coupling loop (``coupling``) that iterates it with the physics leaves."""
