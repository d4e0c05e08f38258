//! The contact LCP solver against independent references: brute-force enumeration of active
//! sets, projected Gauss–Seidel, and the KKT conditions at the solution.

use boltzone::contact::{projected_gauss_seidel, solve_lcp, solve_lcp_from, Lcp, LcpParams};
use nalgebra::{DMatrix, DVector};

/// A small deterministic generator (no dependency): 64-bit LCG, uniform in [-1, 1).
pub(crate) struct Lcg(pub(crate) u64);
impl Lcg {
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
}

/// A random SPD matrix B Bᵀ + δ I.
fn spd(n: usize, rng: &mut Lcg, delta: f64) -> DMatrix<f64> {
    let b = DMatrix::from_fn(n, n, |_, _| rng.next());
    &b * b.transpose() + DMatrix::identity(n, n) * delta
}

/// A flexibility like a plate's: smooth decaying kernel plus a local spring.
fn plate_like(n: usize) -> DMatrix<f64> {
    DMatrix::from_fn(n, n, |i, j| {
        let d = (i as f64 - j as f64).abs() / 4.0;
        (-d).exp() * (1.0 + d) + if i == j { 0.1 } else { 0.0 }
    })
}

/// All 2^m active sets: returns the forces of every set that satisfies the Signorini conditions.
fn enumerate(lcp: &Lcp) -> Vec<DVector<f64>> {
    let m = lcp.points();
    let n = lcp.gap0.len();
    let mut found = Vec::new();
    for mask in 0u32..(1 << m) {
        let act: Vec<usize> = (0..m).filter(|i| mask & (1 << i) != 0).collect();
        let mut idx = act.clone();
        if lcp.welded {
            idx.extend(act.iter().map(|i| m + i));
        }
        let mut l = DVector::zeros(n);
        if !idx.is_empty() {
            let a = lcp.flexibility.select_rows(&idx).select_columns(&idx);
            // LU, not Cholesky: an independent dense solve.
            let x = a
                .lu()
                .solve(&-DVector::from_iterator(
                    idx.len(),
                    idx.iter().map(|&i| lcp.gap0[i]),
                ))
                .unwrap();
            for (k, &i) in idx.iter().enumerate() {
                l[i] = x[k];
            }
        }
        let g = &lcp.gap0 + &lcp.flexibility * &l;
        let scale = lcp.gap0.amax();
        let ok = (0..m).all(|i| {
            if mask & (1 << i) != 0 {
                l[i] >= 0.0
            } else {
                g[i] >= -1e-13 * scale
            }
        });
        if ok {
            found.push(l);
        }
    }
    found
}

#[test]
fn matches_enumeration_on_random_problems() {
    let mut rng = Lcg(7);
    let mut welded_missed = 0;
    let mut welded_fallback = 0;
    for trial in 0..200 {
        let m = 1 + trial % 9;
        let welded = trial % 3 == 2;
        let n = if welded { 2 * m } else { m };
        let f = spd(n, &mut rng, 0.05);
        let q = DVector::from_fn(n, |_, _| rng.next());
        let lcp = Lcp {
            flexibility: f,
            gap0: q,
            welded,
        };
        let all = enumerate(&lcp);
        let res = solve_lcp(&lcp, &LcpParams::default());
        let res = res.unwrap_or_else(|e| panic!("trial {trial}: {e}"));
        if res.info.prefix {
            // Pivoting found no solution (none may exist): the report's rule — a contact zone
            // from the first point on, all normal forces compressive, the longest such.
            assert!(welded, "trial {trial}: fallback on a frictionless problem");
            let k = res.info.active;
            assert!(res.active.iter().enumerate().all(|(i, &a)| a == (i < k)));
            assert!((0..k).all(|i| res.force[i] >= -1e-10 * res.force.amax()));
            welded_fallback += 1;
            if all.is_empty() {
                continue;
            }
            // A solution exists but the pivoting missed it: the fallback must be it if it is a
            // contiguous zone; otherwise count the miss.
            if res.info.residual > 1e-9 {
                welded_missed += 1;
                continue;
            }
        }
        let s = res;
        // For SPD F the frictionless LCP has exactly one solution (enumeration checks it below).
        assert!(
            !all.is_empty(),
            "trial {trial}: enumeration found no solution"
        );
        let best = all
            .iter()
            .map(|l| (l - &s.force).amax())
            .fold(f64::INFINITY, f64::min);
        // Both are dense solves of the same small systems with cond ≲ 1e4: 1e-10 absolute on
        // forces of order one.
        assert!(
            best < 1e-10,
            "trial {trial}: differs from enumeration by {best}"
        );
        if !welded {
            assert_eq!(
                all.len(),
                1,
                "trial {trial}: P-matrix LCP must have one solution"
            );
        }
        assert!(
            s.info.residual < 1e-12,
            "trial {trial}: KKT residual {}",
            s.info.residual
        );
    }
    eprintln!(
        "welded random problems: {welded_fallback} fell back to the contiguous rule, \
         {welded_missed} of them although a Signorini solution exists"
    );
}

#[test]
fn kkt_conditions_hold_and_pgs_agrees() {
    for m in [10, 40, 120] {
        let f = plate_like(m);
        // A load that pushes the first third in and lifts the rest, smoothly.
        let q = DVector::from_fn(m, |i, _| (i as f64 / m as f64 - 0.35) * 2.0);
        let lcp = Lcp::frictionless(f.clone(), q.clone());
        let s = solve_lcp(&lcp, &LcpParams::default()).unwrap();
        let lmax = s.force.amax();
        for i in 0..m {
            assert!(
                s.force[i] >= -1e-12 * lmax,
                "m={m}: λ[{i}] = {}",
                s.force[i]
            );
            assert!(s.gap[i] >= -1e-12, "m={m}: g[{i}] = {}", s.gap[i]);
            assert!(
                (s.force[i] * s.gap[i]).abs() <= 1e-12 * lmax,
                "m={m}: λg at {i}"
            );
        }
        // The gap is what the forces produce.
        let g = &q + &f * &s.force;
        assert!((g - &s.gap).amax() < 1e-13);
        let (pgs, sweeps) = projected_gauss_seidel(&f, &q, 1e-15, 200_000);
        assert!(sweeps < 200_000, "m={m}: PGS did not converge");
        // PGS stops when a sweep changes no force by more than 1e-15 relative; its error is that
        // times the contraction factor's condition, so 1e-9 relative is generous but meaningful.
        let d = (&pgs - &s.force).amax() / lmax;
        assert!(d < 1e-9, "m={m}: PGS differs by {d}");
    }
}

#[test]
fn warm_start_and_scaling() {
    let m = 60;
    let f = plate_like(m);
    let q = DVector::from_fn(m, |i, _| (i as f64 / m as f64 - 0.5).powi(3) * 8.0 + 0.1);
    let lcp = Lcp::frictionless(f.clone(), q.clone());
    let cold = solve_lcp(&lcp, &LcpParams::default()).unwrap();
    let warm = solve_lcp_from(&lcp, &LcpParams::default(), Some(&cold.active)).unwrap();
    assert_eq!(warm.info.iterations, 1);
    assert_eq!(warm.force, cold.force);
    // Linear scaling of the load scales forces and keeps the active set.
    for s in [1e-3, 1e3] {
        let scaled =
            solve_lcp(&Lcp::frictionless(f.clone(), &q * s), &LcpParams::default()).unwrap();
        assert_eq!(scaled.active, cold.active);
        assert!((&scaled.force / s - &cold.force).amax() < 1e-12 * cold.force.amax());
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let lcp = Lcp::frictionless(DMatrix::identity(2, 3), DVector::zeros(2));
    assert!(solve_lcp(&lcp, &LcpParams::default()).is_err());
    let lcp = Lcp::frictionless(DMatrix::identity(1, 1), DVector::from_vec(vec![f64::NAN]));
    assert!(solve_lcp(&lcp, &LcpParams::default()).is_err());
    // An indefinite "flexibility" is reported, not a panic.
    let lcp = Lcp::frictionless(-DMatrix::identity(1, 1), DVector::from_vec(vec![-1.0]));
    assert!(solve_lcp(&lcp, &LcpParams::default()).is_err());
}
