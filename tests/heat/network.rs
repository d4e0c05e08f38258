//! The Appendix D conductance network (src/heat/network.rs): energy balance, a series chain
//! against its closed form, floating groups, the program's residual.

use boltzone::heat::network::{Network, NetworkError};

use crate::network_fixtures::Rng;

#[test]
fn energy_balance_on_random_networks() {
    let mut rng = Rng::new(7);
    for case in 0..50 {
        let n = 2 + rng.below(60);
        let mut net = Network::new(n).unwrap();
        // A spanning chain keeps the network connected; conductances span `decades` (2 for the
        // first half of the cases, 6 for the rest: badly scaled on purpose).
        let decades = if case < 25 { 2.0 } else { 6.0 };
        let g = |rng: &mut Rng| 10f64.powf(decades * (rng.unit() - 0.5));
        let mut links = Vec::new();
        for i in 1..n {
            links.push((i, i + 1, g(&mut rng)));
        }
        for _ in 0..2 * n {
            let (i, j) = (1 + rng.below(n), 1 + rng.below(n));
            if i != j {
                links.push((i, j, g(&mut rng)));
            }
        }
        for &(i, j, v) in &links {
            net.connect(i, j, v).unwrap();
        }
        // Two grounds 100 degrees apart carry heat through; others at random.
        net.ground(1, 1.0, 50.0).unwrap();
        net.ground(n, 1.0, -50.0).unwrap();
        for _ in 0..rng.below(3) {
            net.ground(
                1 + rng.below(n),
                rng.unit() + 0.01,
                200.0 * rng.unit() - 100.0,
            )
            .unwrap();
        }
        for _ in 0..rng.below(4) {
            net.power(1 + rng.below(n), 50.0 * rng.unit() - 25.0)
                .unwrap();
        }
        let s = net.solve().unwrap();
        // Steady state: what the grounds give plus what the nodes generate is zero.
        let ground: f64 = s.nodes.iter().map(|r| r.ground_flow).sum();
        let power: f64 = s.nodes.iter().map(|r| r.power).sum();
        let throughput: f64 = s
            .nodes
            .iter()
            .map(|r| r.ground_flow.abs() + r.power.abs())
            .sum::<f64>()
            / 2.0;
        // The imbalance is minus the sum of the solve's residuals G T - b, which a backward-stable
        // Cholesky bounds by about n eps |G| |T|: below 1e-10 of the throughput when the
        // conductances span 2 decades; across 6 decades use that bound itself.
        let gmax = links.iter().map(|l| l.2).fold(0.0, f64::max);
        let tmax = s.nodes.iter().map(|r| r.t.abs()).fold(0.0, f64::max);
        let bound = if decades <= 2.0 {
            1e-10 * throughput
        } else {
            n as f64 * f64::EPSILON * 4.0 * gmax * tmax
        };
        assert!(
            (ground + power).abs() <= bound,
            "case {case}: {ground} + {power} (throughput {throughput})"
        );
        // The program's residual |B| - |BC| is at rounding level of B.
        let b = s.nodes.iter().map(|r| r.b.abs()).fold(0.0, f64::max);
        assert!(
            s.residual <= 1e-10 * b.max(1.0),
            "case {case}: residual {}",
            s.residual
        );
    }
}

#[test]
fn series_chain_against_its_closed_form() {
    // Grounds at 100 and -20 through g_0 and g_N, links g_1..g_{N-1}: one flow
    // q = (T_L - T_R) / sum(1/g), and T_i = T_L - q * (resistances up to node i).
    let mut rng = Rng::new(42);
    for &n in &[1usize, 2, 10, 200] {
        let g: Vec<f64> = (0..=n).map(|_| 0.1 + 10.0 * rng.unit()).collect();
        let mut net = Network::new(n).unwrap();
        for (i, &gi) in g.iter().enumerate().take(n).skip(1) {
            net.connect(i, i + 1, gi).unwrap();
        }
        if n == 1 {
            // One node between two grounds is not expressible (one ground per node): use the
            // sum of both conductances at their weighted temperature instead.
            net.ground(1, g[0] + g[1], (100.0 * g[0] - 20.0 * g[1]) / (g[0] + g[1]))
                .unwrap();
        } else {
            net.ground(1, g[0], 100.0).unwrap();
            net.ground(n, g[n], -20.0).unwrap();
        }
        let s = net.solve().unwrap();
        let total: f64 = g.iter().map(|x| 1.0 / x).sum();
        let q = 120.0 / total;
        let mut r = 0.0;
        for (i, gi) in g.iter().take(n).enumerate() {
            r += 1.0 / gi;
            let exact = 100.0 - q * r;
            assert!(
                (s.nodes[i].t - exact).abs() < 1e-11 * 100.0,
                "n {n} node {}: {} vs {exact}",
                i + 1,
                s.nodes[i].t
            );
        }
        if n > 1 {
            assert!((s.nodes[0].ground_flow - q).abs() < 1e-11 * q, "n {n}");
        }
    }
}

#[test]
fn floating_groups_and_bad_values_are_named() {
    let mut net = Network::new(4).unwrap();
    net.connect(1, 2, 1.0).unwrap();
    net.connect(3, 4, 1.0).unwrap();
    net.ground(1, 1.0, 0.0).unwrap();
    let e = net.solve().unwrap_err();
    assert_eq!(e, NetworkError::Floating { node: 3, size: 2 });
    assert!(e.to_string().contains("node 3"));
    assert!(net
        .connect(2, 2, 1.0)
        .unwrap_err()
        .to_string()
        .contains("node 2 to itself"));
    assert!(net
        .connect(1, 5, 1.0)
        .unwrap_err()
        .to_string()
        .contains("node 5 is not in 1..=4"));
    let e = net.connect(1, 3, -2.0).unwrap_err().to_string();
    assert!(e.contains("conductance of node 1 = -2"), "{e}");
    let e = net.ground(2, 1.0, f64::INFINITY).unwrap_err().to_string();
    assert!(e.contains("ground temperature of node 2 = inf"), "{e}");
    assert_eq!(Network::new(0).unwrap_err(), NetworkError::Empty);
}

#[test]
fn printout_names_its_units() {
    let mut net = Network::new(2).unwrap();
    net.connect(1, 2, 2.0).unwrap();
    net.ground(1, 1.0, 10.0).unwrap();
    net.power(2, 3.0).unwrap();
    let text = net.solve().unwrap().to_string();
    assert!(text.contains("units:") && text.contains("GRD. COND.") && text.contains("RESIDUAL"));
    // Node 2 feeds 3 into node 1 and on to ground: T1 = 10 + 3, T2 = T1 + 3/2.
    let s = net.solve().unwrap();
    assert!((s.nodes[0].t - 13.0).abs() < 1e-13 && (s.nodes[1].t - 14.5).abs() < 1e-13);
}
