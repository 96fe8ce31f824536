"""springblock.Scene takes the command line's fields, defaults, units and checks."""
import numpy as np
import pytest

import springblock as sb

SMALL = dict(N=20, reps=1, duration="3t0", pattern="periodic:2,1")


def test_keywords_and_dict_give_the_same_scene():
    assert sb.Scene(**SMALL).to_dict() == sb.Scene(SMALL).to_dict()


def test_keywords_override_the_dict():
    assert sb.Scene({"N": 30, "reps": 2}, N=40).to_dict()["geometry"]["N"] == 40


def test_scene_matches_the_command_line(cli):
    # Defaults and unit conversion are the command line's: the JSON scene is identical.
    args = ["--N", 20, "--reps", 1, "--duration", "3t0", "--pattern", "periodic:2,1", "--length", "7.2cm",
            "--damping", "5/ms", "--velocity", "0.1cm/s"]
    expected = cli("run", *args, "--json")["scene"]
    scene = sb.Scene(SMALL, length="7.2cm", damping="5/ms", velocity="0.1cm/s")
    assert scene.to_dict() == expected


def test_numbers_are_accepted_where_the_cli_takes_a_plain_number():
    by_text = sb.Scene(N="30", length="0.05", k_int_scale="0.5", tol="1e-9", stop_after_mu_s="true")
    by_number = sb.Scene(N=30, length=0.05, k_int_scale=0.5, tol=1e-9, stop_after_mu_s=True)
    by_numpy = sb.Scene(N=np.int64(30), length=np.float64(0.05), k_int_scale=np.float32(0.5), tol=1e-9,
                        stop_after_mu_s=True)
    assert by_text.to_dict() == by_number.to_dict() == by_numpy.to_dict()


def test_whole_float_is_a_whole_number():
    assert sb.Scene(N=30.0).N == 30


@pytest.mark.parametrize("fields, field, words", [
    ({"colour": "red"}, "colour", "unknown scene field"),
    ({"velocity": "-3cm/s"}, "velocity", "outside the allowed range"),
    ({"length": "4 parsecs"}, "length", "unknown unit"),
    ({"N": 0}, "N", "outside [1, 1000000]"),
    ({"N": 2.5}, "N", "not a whole number"),
    ({"reps": True}, "reps", "not a whole number"),
    ({"pattern": "periodic:60,1", "N": 50}, "pattern", "exceeds the number of blocks"),
    ({"damping": [1, 2]}, "damping", "string, number or boolean"),
    ({"mu_s": "1.0,0.1", "mu_d": "1.5,0.01"}, "mu_d", "[0, mu_s mean = 1]"),
    ({"stop_after_mu_s": "maybe"}, "stop_after_mu_s", "not true or false"),
])
def test_bad_input_raises_value_error_naming_the_field(fields, field, words):
    with pytest.raises(ValueError) as raised:
        sb.Scene(**fields)
    assert isinstance(raised.value, sb.InputError)
    assert raised.value.field == field
    assert str(raised.value).startswith(f"invalid {field}:")
    assert words in str(raised.value)


def test_python_and_cli_refuse_with_the_same_message(cli):
    done = cli("run", "--N", 0, check=False)
    assert done.returncode == 2
    with pytest.raises(ValueError) as raised:
        sb.Scene(N=0)
    assert f"springblock: {raised.value}" in done.stderr


def test_a_dict_is_required():
    with pytest.raises(ValueError, match="dict"):
        sb.Scene([("N", 3)])


def test_replace_validates_again():
    scene = sb.Scene(**SMALL)
    assert scene.replace(reps=3).reps == 3 and scene.reps == 1
    with pytest.raises(ValueError, match="invalid seed"):
        scene.replace(seed=-1)


def test_every_field_is_listed_and_its_example_is_accepted():
    fields = sb.scene_fields()
    keys = [f["key"] for f in fields]
    assert {"N", "length", "pattern", "mu_s", "reps", "seed", "threads", "stress_times"} <= set(keys)
    for f in fields:
        if f["key"] in ("pattern", "k_int_scale", "stress_times", "sample_dt", "duration", "materials"):
            continue  # examples that need other fields (a surface as long as N, a long run, a file of N rows)
        sb.Scene(**{f["key"]: f["example"]})
