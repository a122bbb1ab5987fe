"""HTML reports: generic page pieces (:mod:`.html`) and the shared style sheet ``style.css``.

The study modules build their pages from these pieces (e.g. :mod:`bearingsim.studies.hub_report`).
"""
