"""springblock.theory: the closed forms, and the prediction `springblock theory` prints."""
import numpy as np
import pytest

import springblock as sb


def test_of_scene_is_the_theory_command(cli):
    expected = cli("theory", "--mu-d", "0.6,0.05", "--N", 50, "--json")
    assert sb.theory.of_scene(sb.Scene(mu_d="0.6,0.05", N=50)) == expected


def test_cycle_of_the_scene_block():
    block = sb.theory.single_block(sb.Scene())
    c = sb.theory.cycle(block, 1.0, 0.5)
    assert c.omega == pytest.approx(np.sqrt(block.k_N_per_m / block.m_kg))
    assert c.mu_d_macro == pytest.approx(0.5)


def test_positions_take_a_time_or_an_array():
    block = sb.theory.SingleBlock(m_kg=1e-3, k_N_per_m=10.0, v_m_per_s=1e-3, F_n_N=1.0)
    t = np.linspace(0, 1e-2, 5)
    x = sb.theory.x_sliding(block, 1.0, 0.5, t)
    assert x.shape == t.shape
    assert x[2] == sb.theory.x_sliding(block, 1.0, 0.5, float(t[2]))
    assert sb.theory.xdot_sliding(block, 1.0, 0.5, t.reshape(5, 1)).shape == (5, 1)


def test_mu_d_above_mu_s_is_refused():
    block = sb.theory.SingleBlock(1e-3, 10.0, 1e-3, 1.0)
    with pytest.raises(ValueError):
        sb.theory.cycle(block, 0.5, 1.0)


def test_submodule_imports():
    import springblock.theory as theory
    assert theory is sb.theory


def test_of_scene_takes_materials_like_the_command(cli, tmp_path):
    """Per-block coefficients as Python arrays and as a file give the same chain prediction."""
    mu_d = np.linspace(0.2, 0.7, 6)
    path = tmp_path / "graded.tsv"
    path.write_text("mu_d\n" + "".join(f"{x!r}\n" for x in mu_d))
    expected = cli("theory", "--N", 6, "--materials", path, "--json")["chain"]
    chain = sb.theory.of_scene(sb.Scene(N=6, materials={"mu_d": mu_d}))["chain"]
    assert chain == expected
    assert chain["n_contact"] == 6 and chain["quadratures"] == 6
    assert chain["mu_d_macro_gaussian"] == pytest.approx(np.mean(chain["block_mu_d_macro"]), rel=1e-14)
