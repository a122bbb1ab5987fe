"""Arrangement files (bearing sets and double-row units, TOML with units) →
:class:`~bearingsim.statics.arrangements.BearingSystem`.

A bearing file with ``rows`` or ``arrangement`` is read here (:func:`bearingsim.io.bearing.bearing_from_dict`
hands it over).  The model (rows on a rigid shaft and housing, preload by offset or force) stays in
:mod:`bearingsim.statics.arrangements`; this module only reads: units are parsed into SI floats here.
"""

from __future__ import annotations

import dataclasses

from ..errors import InputError
from ..geometry import BallBearing
from ..statics.arrangements import MAX_SPAN_PER_PITCH, BearingSystem, Row, make_system, offset_for_preload
from ..units import parse_quantity
from .bearing import bearing_from_dict, check_sleeves, load_bearing, rings_from_dict
from .clearance import operating_clearance_from_dict

_KEYS = {"name", "description", "type", "arrangement", "row", "bearing", "rows", "row_spacing", "preload",
         "preload_offset", "load_point", "dynamic_load_rating", "sources", "clearance", "rings"}
_ROW_KEYS = {"bearing", "position", "orientation", "axial_offset", "first_ball_azimuth"}


def _row_bearing(spec, field_name: str) -> BallBearing:
    if isinstance(spec, dict):
        b = bearing_from_dict(spec)
    elif isinstance(spec, str):
        b = load_bearing(spec)
    else:
        raise InputError(field_name, f"expected a catalogue name, a path or a table, got {spec!r}",
                         'e.g. row = "hub-seed001-row"')
    if not isinstance(b, BallBearing):
        raise InputError(field_name, "a row must be a single-row bearing", "refer to a single-row entry")
    return b


def arrangement_from_dict(data: dict) -> BearingSystem:
    """Build a :class:`BearingSystem` from a TOML table (units parsed here).

    Two forms::

        arrangement = "DB"            # DB, DF, DT
        row = "skf-7011-cdga-hc"      # catalogue name, TOML path, or an inline table
        row_spacing = "18 mm"         # default: the row bearing's width
        preload = "150 N"             # or preload_offset = "8 um" (total of the set)
        load_point = "0 mm"

    or explicit rows::

        [[rows]]
        bearing = "hub-seed001-row"
        position = "-9.1 mm"
        orientation = 1
        axial_offset = "10 um"

    An optional ``[rings]`` table (:mod:`bearingsim.rings.spec`: ring model, seat sleeves, the boundary dimensions
    of a double-row unit's shared outer ring and of its inner rings) is kept in ``notes["rings"]``.

    An optional ``[clearance]`` table (:func:`bearingsim.io.clearance.operating_clearance_from_dict`:
    fits, temperatures, speed) is applied after the preload: the preload of the file is the preload of
    the set as supplied (unmounted, at the reference temperature); the operating preload before and after
    is reported in ``notes["operating_clearance"]``.
    """
    unknown = sorted(set(data) - _KEYS)
    if unknown:
        raise InputError(unknown[0], "unknown key in arrangement file", f"known keys: {', '.join(sorted(_KEYS))}")
    name = str(data.get("name", "bearing system"))
    notes = dict(data.get("sources", {}))
    if "description" in data:
        notes["description"] = data["description"]
    if "rings" in data:  # ring model, seat sleeves and the shared ring dimensions of a unit (rings.spec)
        notes["rings"] = rings_from_dict(data["rings"], unit=True)
    load_point = parse_quantity(data["load_point"], "length", "load_point") if "load_point" in data else 0.0
    rating = parse_quantity(data["dynamic_load_rating"], "force", "dynamic_load_rating") \
        if "dynamic_load_rating" in data else None
    preload = parse_quantity(data["preload"], "force", "preload") if "preload" in data else None
    offset = parse_quantity(data["preload_offset"], "length", "preload_offset") if "preload_offset" in data else None
    clearance_change = None
    if "clearance" in data:
        clearance_change = operating_clearance_from_dict(data["clearance"], "clearance")
    if "rows" in data:
        if "arrangement" in data and str(data["arrangement"]).lower() != "custom":
            raise InputError("arrangement", "give either arrangement (with row) or [[rows]], not both",
                             "remove one of them")
        rl = data["rows"]
        if not isinstance(rl, list) or not rl:
            raise InputError("rows", "expected a list of [[rows]] tables", "add [[rows]] tables")
        rows = []
        for i, t in enumerate(rl):
            f = f"rows[{i}]"
            if not isinstance(t, dict):
                raise InputError(f, "expected a table", "write [[rows]] tables")
            bad = sorted(set(t) - _ROW_KEYS)
            if bad:
                raise InputError(f"{f}.{bad[0]}", "unknown key", f"known keys: {', '.join(sorted(_ROW_KEYS))}")
            if "bearing" not in t:
                raise InputError(f"{f}.bearing", "missing", "give the row's bearing (catalogue name or path)")
            if "position" not in t:
                raise InputError(f"{f}.position", "missing", 'e.g. position = "-9.1 mm"')
            o = t.get("orientation", 1)
            if isinstance(o, str):
                o = o.strip()
                o = {"+1": 1, "1": 1, "-1": -1}.get(o, o)
            if o not in (1, -1):
                raise InputError(f"{f}.orientation", f"must be 1 or -1, got {o!r}", "orientation = 1 or -1")
            rows.append(Row(_row_bearing(t["bearing"], f"{f}.bearing"),
                            parse_quantity(t["position"], "length", f"{f}.position"), float(o),
                            parse_quantity(t["axial_offset"], "length", f"{f}.axial_offset")
                            if "axial_offset" in t else 0.0,
                            parse_quantity(t["first_ball_azimuth"], "angle", f"{f}.first_ball_azimuth")
                            if "first_ball_azimuth" in t else 0.0))
        if offset is not None:
            raise InputError("preload_offset", "with [[rows]] give axial_offset per row", "move it into the rows")
        pl = 0.0
        if preload is not None:
            e = offset_for_preload(rows, preload)
            rows = [dataclasses.replace(r, axial_offset=e) for r in rows]
            pl = preload
        system = BearingSystem(name, tuple(rows), load_point, "custom", pl,
                               rating if rating is not None else 0.0, notes)
    else:
        if "arrangement" not in data:
            raise InputError("arrangement", "missing", 'give arrangement = "DB" with row = ..., or [[rows]]')
        spec = data.get("row", data.get("bearing"))
        if spec is None:
            raise InputError("row", "missing", 'give the single-row bearing, e.g. row = "skf-7011-cdga-hc"')
        b = _row_bearing(spec, "row")
        spacing = parse_quantity(data["row_spacing"], "length", "row_spacing") if "row_spacing" in data else None
        system = make_system(b, data["arrangement"], spacing, preload, offset, load_point, name, rating, notes)
    dm = max(r.bearing.pitch_diameter for r in system.rows)
    if abs(load_point) > MAX_SPAN_PER_PITCH * dm:
        raise InputError("load_point", f"{load_point * 1e3:.4g} mm from the set's centre is more than "
                         f"{MAX_SPAN_PER_PITCH:g} pitch diameters away", "check the value and its unit (e.g. "
                         "\"10.4 mm\"); give a far load as the force and moment it puts at the set")
    if "rings" in notes:
        spec = notes["rings"]
        od = spec.outer_ring[0] or max(r.bearing.outside_diameter for r in system.rows)
        bore = spec.inner_rings[0] or min(r.bearing.bore if r.bearing.bore > 0 else float("inf") for r in system.rows)
        check_sleeves(spec, 0.0 if bore == float("inf") else bore, od)
    if clearance_change is not None:
        system = clearance_change.apply(system)
    return system
