"""Dynamic bearing engine: rings, balls and cage in time.

Public entry points: :func:`bearingsim.dynamics.run.simulate` and the case file reader
:func:`bearingsim.dynamics.case.load_case`.
"""
