"""The nut's own bearing face (`load.nut_outer_radius`, issue 33 item 5) through Python: the
scene dict goes through the same parser, so the answer is `boltzone two --b2`'s bit for bit, a
bolt fills B2 from the catalogue's nut, and a bad B2 is an InputError naming the key."""

import boltzone
import pytest
from conftest import cli_json

SCENE = {"units": "m-Pa-N", "method": "fem", "hole": {"radius": 0.0055},
         "load": {"outer_radius": 0.008, "nut_outer_radius": 0.0095, "force": 20e3},
         "plates": [{"thickness": 0.01, "material": {"E": 205e9, "nu": 0.3}}],
         "joint": {"outer_radius": 0.02}, "outputs": {"stiffness": True}}


def test_nut_face_equals_two_b2():
    py = boltzone.solve(SCENE).to_dict()
    two = cli_json("two", "--units", "m-Pa-N", "--a", "0.0055", "--b", "0.008", "--b2",
                   "0.0095", "--d", "0.01", "--c", "0.02", "--e", "205e9", "--force", "20e3",
                   "--stiffness", "--method", "fem", "--json")
    for key in ["r_o", "r_o_error", "member_stiffness", "member_compliance",
                "rules_member_stiffness"]:
        assert py[key] == two[key], key


def test_bolt_fills_the_nut_face_from_the_catalogue():
    s = boltzone.Scene({"units": "mm-MPa-N", "bolt": {"size": "M10"},
                        "preload": {"force": 20e3},
                        "plates": [{"thickness": 10.0, "material": {"E": 205e3, "nu": 0.3}}]})
    load = s.to_dict()["load"]
    assert (load["outer_radius"], load["nut_outer_radius"]) == (7.315, 7.3)  # ISO 4017, 4032


def test_bad_nut_face_names_the_key():
    bad = dict(SCENE, load=dict(SCENE["load"], nut_outer_radius=0.005))
    with pytest.raises(boltzone.InputError, match="load.nut_outer_radius"):
        boltzone.solve(bad)
