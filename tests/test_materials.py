"""Material classes and masses: every generated object weighs what real objects of its
category weigh, and the exported URDF carries the same masses."""

from __future__ import annotations

import dataclasses
import xml.etree.ElementTree as ET

import pytest

import artipg
from artipg.export.meshes import object_mass
from artipg.export.urdf import build_urdf
from artipg.materials import CLASS_DENSITY, MATERIAL, density, material_class
from artipg.rules import Category

CATEGORIES = artipg.categories()
SEEDS = range(6)


@pytest.mark.parametrize("category", CATEGORIES)
def test_masses_are_plausible_for_the_category(category):
    rule = artipg.get_category(category)
    lo, hi = rule.mass_range
    assert hi < float("inf"), f"{category}: declare Category.mass_range (plausible real-world mass, kg)"
    for seed in SEEDS:
        obj = artipg.generate(category, seed)
        m = object_mass(obj)
        assert lo <= m <= hi, f"{category}/{seed} ({obj.subcategory}): {m:.3f} kg outside {rule.mass_range}"


def test_category_materials_override_the_label_defaults():
    obj = artipg.generate("refrigerator", 0)
    assert obj.materials["body"] == "insulated"
    assert material_class("body", obj.materials) == "insulated"
    assert material_class("body") == MATERIAL["body"]
    assert density("body", obj.materials) == CLASS_DENSITY["insulated"] < density("body")
    # labels the category does not mention keep their default
    assert material_class("handle", obj.materials) == MATERIAL["handle"]


def test_mass_range_catches_a_wrong_material():
    """The same refrigerator with solid-wood walls (no category overrides) weighs far
    more than any real one: the range test would catch that mistake."""
    obj = artipg.generate("refrigerator", 1)
    lo, hi = artipg.get_category("refrigerator").mass_range
    assert lo <= object_mass(obj) <= hi
    obj.materials = {}
    assert object_mass(obj) > hi


def test_urdf_masses_use_the_category_materials():
    obj = artipg.generate("laptop", 3)
    robot, _ = build_urdf(obj, visuals=False)
    total = sum(float(m.get("value")) for m in robot.iter("mass"))
    assert total == pytest.approx(object_mass(obj), rel=1e-6)
    # the aluminium base of a laptop outweighs its lid, as in real laptops
    masses = {lk.get("name"): float(lk.find("inertial/mass").get("value")) for lk in robot.iter("link")}
    root = obj.links[0].name
    lid = next(j.child for j in obj.joints if j.parent == root and j.movable)
    assert masses[root] > masses[lid], ET.tostring(robot)[:200]


def test_category_rejects_unknown_materials_and_bad_mass_ranges():
    rule = artipg.get_category("kettle")
    with pytest.raises(ValueError, match="unknown material classes"):
        Category(rule.name, rule.subcategories, rule.slots, materials={"body": "unobtainium"})
    with pytest.raises(ValueError, match="mass_range"):
        dataclasses.replace(rule, mass_range=(2.0, 1.0))
