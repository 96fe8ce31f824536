"""A pattern given block by block: numpy arrays (0/1 or bool), lists and the command line's mask
strings are one surface, and a mask equal to a periodic surface gives its numbers to the last bit."""
import numpy as np
import pytest

import springblock as sb

RUN = dict(N=40, reps=3, seed=7, duration="3t0")
# periodic:2,6 on 40 blocks, laid out by the default (symmetric) rule, written out by hand: of the
# phases whose mask reads the same backwards (1 and 5 in "block j is a pawl iff (j + phase) mod 8 < 2"),
# the rule takes the one with pawl pieces at both ends, 1.
PERIODIC = np.array([(j + 1) % 8 < 2 for j in range(40)])


def test_the_hand_written_mask_is_periodic_2_6(cli):
    done = cli("pattern", "--N", 40, "--pattern", "periodic:2,6", check=False)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[0] == "".join("1" if b else "0" for b in PERIODIC)


@pytest.mark.parametrize("form", [PERIODIC, PERIODIC.astype(np.int8), PERIODIC.astype(float), list(PERIODIC.astype(int)),
                                  tuple(bool(b) for b in PERIODIC),
                                  "mask:" + "".join("1" if b else "0" for b in PERIODIC)])
def test_every_form_is_the_same_scene(form):
    assert sb.Scene(pattern=form, **RUN).to_dict() == sb.Scene(pattern=PERIODIC, **RUN).to_dict()


def test_a_mask_equal_to_a_periodic_surface_gives_its_numbers():
    periodic = sb.run(sb.Scene(pattern="periodic:2,6", **RUN))
    masked = sb.run(sb.Scene(pattern=PERIODIC, **RUN))
    assert list(masked.mu_s.values) == list(periodic.mu_s.values)
    assert list(masked.mu_d.values) == list(periodic.mu_d.values)
    assert masked.mu_s.mean == periodic.mu_s.mean and masked.mu_d.mean == periodic.mu_d.mean


def test_the_scene_records_the_blocks():
    scene = sb.Scene(pattern=PERIODIC, **RUN).to_dict()
    assert scene["pattern"] == "mask:" + "".join("1" if b else "0" for b in PERIODIC)
    record = scene["pattern_mask"]
    assert record["source"] == "inline" and record["blocks"] == 40 and record["contacts"] == 10
    assert len(record["fnv1a64"]) == 16


def test_a_mask_file_and_its_array_are_one_surface(tmp_path):
    path = tmp_path / "surface.txt"
    digits = "".join("1" if b else "0" for b in PERIODIC)
    path.write_text("# periodic:2,6\n" + digits[:20] + "\n  " + digits[20:] + "\n")
    from_file = sb.Scene(pattern=f"mask:@{path}", **RUN).to_dict()
    assert from_file["pattern"] == f"mask:@{path}"
    assert from_file["pattern_mask"]["mask"] == digits
    assert from_file["pattern_mask"]["fnv1a64"] == sb.Scene(pattern=PERIODIC, **RUN).to_dict()["pattern_mask"]["fnv1a64"]


@pytest.mark.parametrize("pattern, words", [
    (np.zeros((2, 20)), "one dimension, got ndim = 2"),
    ([0, 2] + [1] * 38, "mask entry at index 1 is 2"),
    (["1"] * 40, "mask entry at index 0 is '1'"),
    (np.full(40, 0.5), "mask entry at index 0 is 0.5"),
    (np.zeros(40, dtype=bool), "no block in contact"),
    (np.ones(39, dtype=bool), "the mask has 39 blocks but the chain has N = 40"),
    ([], "empty mask"),
    (3, "got 3"),
])
def test_bad_masks_raise_input_error_naming_the_field(pattern, words):
    with pytest.raises(sb.InputError) as e:
        sb.Scene(pattern=pattern, **RUN)
    assert "pattern" in str(e.value) and words in str(e.value)
