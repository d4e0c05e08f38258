//! The command line under random argument sets (seeded, so every failure reproduces): bad values
//! of every kind and extreme but valid geometry — D/A ∈ [1e-3, 1e3], B/A ∈ [1.001, 1e3],
//! C/B ∈ [1.05, 1e6] or infinite, ν ∈ [−0.9, 0.499], modulus contrast 1e-4…1e4 — over every
//! command. Each run must end by itself within 30 s of CPU (its own user + system time, on one
//! rayon thread: what the run costs, whatever else loads the machine; a 120 s wall limit catches a
//! run that waits without computing), stay under 2 GiB of resident memory, exit
//! with 0–3 (0 converged, 1 failure, 2 bad input, 3 not converged; never a panic's 101), print
//! no NaN, infinity or null where a number is due, and on exit 2 name the flag it rejects.
//!
//! CI runs `FUZZ_RUNS` sets (default 200) on two threads; the full study of 10⁴ sets is
//! `every_command_survives_ten_thousand_argument_sets` (ignored: ~10 min on two cores). Its last run
//! (24 Nov 2026, with `two --method hankel|auto` added) found 10 runs over 30 s, all `two
//! --method hankel` with a hole and B/D from 42 to 625; that route now refuses B/D > 16 with exit
//! 2 naming `--b` (its cost grows like (B/D)²: 18 s and 2.0 GB at 32). The next (24 Nov 2026,
//! after the Hankel route gained the finite rim `--c`; 902 s, codes 4805/81/4971/140) found 9
//! texts "R_o(C = inf)" read as an infinity (now "R_o(infinite plate)") and 3 runs over 30 s,
//! all `two --method hankel --c` with holes of A/D 0.001–0.005, where the route left residual
//! tractions of 1e1–1e4 P: holes below A/D = 0.04 are now refused (exit 2 naming `--a`), and a
//! rim beyond B/D = 8. Re-run (25 Nov 2026, 1487 s on two threads beside other work): passed,
//! codes 4796/76/4992/136, slowest 14.5 s of CPU; the run before it, against a 30 s wall limit
//! at load ~10, had counted 36 `table1`/`table2 --tol 1e-320` runs (7.5–9 s of CPU each on one
//! thread, as at 1e-5) and two B/D = 8 rims at --tol 1.4e-4 (11 s of CPU, 25 trial radii: the
//! rim's search, since made the infinite route's) over the limit, hence the CPU clock.
//! Re-run twice on 25 Nov 2026 after the holed route's knobs came to double their hole modes
//! (to 128 for 1e-5 and 1e-6) and to hand a run short of its tolerance to the next tier: the
//! first (487 s, codes 4804/76/4987/133) passed with its slowest run at 29.6 s of CPU, a
//! narrow load on a small hole with a rim taken through every tier (now stopped where the next
//! tier allows no more modes); the second (601 s beside other work, the same codes) with its
//! slowest at 15.9 s. Runs over 10 s of CPU are printed with their arguments, and with
//! `FUZZ_SHOW_FAILURES` set every run that exits 1 (a failure the user sees) with the first line
//! of its message. Its 76 exit-1 runs (25 Nov 2026) were mostly answers the commands failed to
//! give: short thick plates in full contact (`single`, 14; now R_o = C,
//! `tests/fem/full_contact.rs`), a contact edge a node inside the rim (`two`, 9;
//! `tests/contact/near_rim.rs`); besides them honest limits (`single --method hankel` on slabs
//! thinner than its quadrature's budget, 15; welded dissimilar plates whose contact problem is
//! defective, 16, now saying what to use instead). Re-run after those fixes (831 s beside a CI
//! run): passed, codes 4827/52/4987/134, slowest 16.3 s; of its 52 exit-1 runs, 3 were B = 1e-320
//! (now bad input, exit 2: `tests/cli/regressions.rs`).

use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use boltzone::numerics::random::SplitMix64 as Rng;

/// A bad value for any numeric flag.
fn bad_value(rng: &mut Rng) -> String {
    rng.pick(&[
        "-1", "0", "-0", "nan", "inf", "-inf", "1e309", "abc", "", "1e-320", "--", "0x10",
    ])
    .to_string()
}

/// One argument set: the command and its flags, valid geometry with bad values mixed in.
fn argument_set(rng: &mut Rng) -> Vec<String> {
    let command = *rng.pick(&[
        "two", "two", "two", "single", "single", "slab", "table1", "table2", "map", "none",
    ]);
    let d = rng.log_uniform(1e-3, 1e3) * if rng.chance(0.5) { 1.0 } else { 1e-4 };
    let a = if rng.chance(0.15) {
        0.0
    } else {
        d * rng.log_uniform(1e-3, 1e3)
    };
    let b = if a > 0.0 {
        a * rng.log_uniform(1.001, 1e3)
    } else {
        d * rng.log_uniform(1e-2, 1e2)
    };
    let c = b * rng.log_uniform(1.05, 1e6);
    let nu = -0.9 + rng.unit() * (0.499 + 0.9);
    let mut args: Vec<String> = vec![];
    let flag = |args: &mut Vec<String>, rng: &mut Rng, name: &str, value: String| {
        if rng.chance(0.05) {
            return; // omitted
        }
        args.push(format!("--{name}"));
        args.push(if rng.chance(0.06) {
            bad_value(rng)
        } else {
            value
        });
    };
    match command {
        "two" | "single" | "slab" => {
            args.push(command.into());
            flag(&mut args, rng, "a", format!("{a:e}"));
            flag(&mut args, rng, "b", format!("{b:e}"));
            flag(&mut args, rng, "d", format!("{d:e}"));
            flag(&mut args, rng, "nu", format!("{nu}"));
            if command != "slab" && rng.chance(0.6) {
                flag(&mut args, rng, "c", format!("{c:e}"));
            }
            if rng.chance(0.3) {
                let tol = rng.log_uniform(1e-4, 1e-2);
                flag(&mut args, rng, "tol", format!("{tol:e}"));
            }
        }
        "table1" | "table2" => {
            args.push(command.into());
            // the tables are long: only their checks and one loose run
            let tol = if rng.chance(0.5) {
                bad_value(rng)
            } else {
                "0.02".into()
            };
            args.extend(["--tol".into(), tol]);
            if rng.chance(0.3) {
                args.extend(["--csv".into(), "/".into()]);
            }
        }
        "map" => {
            args.extend(["map".into(), "--n".into(), "2".into()]);
            args.push("--c-over-a".into());
            args.push(if rng.chance(0.5) {
                bad_value(rng)
            } else {
                format!("{:e}", rng.log_uniform(5.5, 1e308))
            });
            args.extend(["--tol".into(), "0.01".into()]);
        }
        _ => {}
    }
    if command == "two" {
        if rng.chance(0.4) {
            let d2 = d * rng.log_uniform(0.2, 5.0);
            flag(&mut args, rng, "d2", format!("{d2:e}"));
        }
        if rng.chance(0.3) {
            let e = 3e7 * rng.log_uniform(1e-2, 1e2);
            flag(&mut args, rng, "e", format!("{e:e}"));
            let contrast = rng.log_uniform(1e-4, 1e4);
            flag(&mut args, rng, "e2", format!("{:e}", e * contrast));
        }
        if rng.chance(0.2) {
            args.extend([
                "--interface".into(),
                rng.pick(&["welded", "frictionless"]).to_string(),
            ]);
        }
        if rng.chance(0.2) {
            args.extend([
                "--load".into(),
                rng.pick(&["uniform", "peak-a", "peak-b"]).to_string(),
            ]);
        }
        if rng.chance(0.1) {
            args.extend([
                "--curve".into(),
                rng.pick(&["/", "/nonexistent/x.csv"]).to_string(),
            ]);
        }
    }
    if command == "two" && rng.chance(0.25) {
        // the semi-analytic routes (with the hole: equal plates; without it: any pair), the tables
        let method = rng.pick(&["hankel", "auto", "table"]);
        args.extend(["--method".into(), method.to_string()]);
    }
    if command == "two" && rng.chance(0.1) {
        // the interface conductance and its heat flags (W/(m·K), in, tan θ, psi)
        args.push("--conductance".into());
        let k = rng.log_uniform(1.0, 400.0);
        flag(
            &mut args,
            rng,
            "conductivity",
            format!("{k:e},{:e}", 0.5 * k),
        );
        let s = rng.log_uniform(1e-7, 1e-3);
        flag(&mut args, rng, "roughness", format!("{s:e}"));
        let (m, h) = (rng.log_uniform(1e-3, 1.0), rng.log_uniform(1e3, 1e7));
        flag(&mut args, rng, "slope", format!("{m:e}"));
        flag(&mut args, rng, "hardness", format!("{h:e}"));
        if rng.chance(0.3) {
            let law = rng.pick(&["cmy1969", "yovanovich1982", "mikic-elastic", "cmy"]);
            args.extend(["--correlation".into(), law.to_string()]);
        }
    }
    if command == "single" && rng.chance(0.4) {
        args.extend(["--method".into(), "hankel".into()]);
    }
    if rng.chance(0.5) && command != "none" {
        args.push("--json".into());
    }
    args
}

/// What one run did.
pub struct Run {
    /// Exit code (None: killed at a time limit).
    pub code: Option<i32>,
    /// Wall seconds.
    pub seconds: f64,
    /// CPU seconds (user + system) last seen while it ran.
    pub cpu_seconds: f64,
    /// Peak resident memory, KiB.
    pub peak_kib: u64,
    /// What it printed.
    pub stdout: String,
    /// Its messages.
    pub stderr: String,
}

/// Resident-set high-water mark of a live process, KiB (0 once it has gone).
fn peak_kib(pid: u32) -> u64 {
    std::fs::read_to_string(format!("/proc/{pid}/status"))
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse().ok())
        })
        .unwrap_or(0)
}

/// CPU seconds (user + system) a live process has used so far (0 once it has gone): fields 14
/// and 15 of `/proc/PID/stat`, in clock ticks of 1/100 s (Linux's `USER_HZ` on every
/// architecture it runs on).
fn cpu_seconds(pid: u32) -> f64 {
    std::fs::read_to_string(format!("/proc/{pid}/stat"))
        .ok()
        .and_then(|s| {
            // the command name (field 2) may hold spaces: count fields after its ')'
            let rest = &s[s.rfind(')')? + 1..];
            let f: Vec<&str> = rest.split_whitespace().collect();
            let ticks = f.get(11)?.parse::<u64>().ok()? + f.get(12)?.parse::<u64>().ok()?;
            Some(ticks as f64 / 100.0)
        })
        .unwrap_or(0.0)
}

/// Wall limit of a run, whatever its CPU limit: a run that waits without computing.
const WALL_LIMIT: Duration = Duration::from_secs(120);

/// Runs the binary on `args` in a scratch directory, killing it once it has used `limit` of CPU
/// (or [`WALL_LIMIT`] of wall time).
pub fn run(args: &[String], limit: Duration) -> Run {
    let dir = std::env::temp_dir().join(format!("boltzone-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let start = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(args)
        .current_dir(&dir)
        .env("RAYON_NUM_THREADS", "1")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let (mut out, mut err) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let reader = std::thread::spawn(move || {
        let (mut o, mut e) = (String::new(), String::new());
        let _ = out.read_to_string(&mut o);
        let _ = err.read_to_string(&mut e);
        (o, e)
    });
    let (mut peak, mut cpu) = (0, 0.0f64);
    let code = loop {
        peak = peak.max(peak_kib(child.id()));
        cpu = cpu.max(cpu_seconds(child.id()));
        if let Some(status) = child.try_wait().unwrap() {
            break status.code();
        }
        if cpu > limit.as_secs_f64() || start.elapsed() > WALL_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let (stdout, stderr) = reader.join().unwrap();
    Run {
        code,
        seconds: start.elapsed().as_secs_f64(),
        cpu_seconds: cpu,
        peak_kib: peak,
        stdout,
        stderr,
    }
}

/// What is wrong with a run, if anything.
fn verdict(args: &[String], r: &Run) -> Option<String> {
    let shown = args.join(" ");
    let Some(code) = r.code else {
        return Some(format!(
            "ran over the time limit ({:.0} s CPU, {:.0} s wall): {shown}",
            r.cpu_seconds, r.seconds
        ));
    };
    if !(0..=3).contains(&code) {
        return Some(format!("exit {code}: {shown}\n{}", r.stderr));
    }
    if r.peak_kib > 2 * 1024 * 1024 {
        return Some(format!("{} MiB resident: {shown}", r.peak_kib / 1024));
    }
    let lower = r.stdout.to_lowercase();
    for bad in ["nan", "inf", "null"] {
        let hit = lower
            .split(|c: char| !c.is_ascii_alphanumeric())
            .any(|w| w == bad || (bad == "inf" && w == "infinity"));
        if hit {
            return Some(format!("'{bad}' in the output: {shown}\n{}", r.stdout));
        }
    }
    if code == 2 && !r.stderr.contains("--") && !r.stderr.contains("usage") {
        return Some(format!(
            "exit 2 without naming a flag: {shown}\n{}",
            r.stderr
        ));
    }
    None
}

/// Runs `n` sets from `seed` on two threads; returns the failures and the slowest run (CPU
/// seconds).
fn campaign(seed: u64, n: usize) -> (Vec<String>, f64, [usize; 4]) {
    let sets: Vec<Vec<String>> = {
        let mut rng = Rng::new(seed);
        (0..n).map(|_| argument_set(&mut rng)).collect()
    };
    let results = std::sync::Mutex::new((Vec::new(), 0.0f64, [0usize; 4]));
    let next = std::sync::atomic::AtomicUsize::new(0);
    std::thread::scope(|s| {
        for _ in 0..2 {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(args) = sets.get(i) else { break };
                let r = run(args, Duration::from_secs(30));
                if r.cpu_seconds > 10.0 {
                    println!("slow: {:.1} s CPU: {}", r.cpu_seconds, args.join(" "));
                }
                if r.code == Some(1) && std::env::var_os("FUZZ_SHOW_FAILURES").is_some() {
                    let why = r.stderr.lines().next().unwrap_or("");
                    println!("exit 1: {}\n    {why}", args.join(" "));
                }
                let mut g = results.lock().unwrap();
                g.1 = g.1.max(r.cpu_seconds);
                if let Some(c) = r.code.filter(|c| (0..=3).contains(c)) {
                    g.2[c as usize] += 1;
                }
                if let Some(v) = verdict(args, &r) {
                    g.0.push(v);
                }
            });
        }
    });
    results.into_inner().unwrap()
}

#[test]
fn every_command_survives_random_argument_sets() {
    let n = std::env::var("FUZZ_RUNS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(200);
    let (failures, slowest, codes) = campaign(0x0B01_7204E, n);
    println!("{n} sets: exit codes 0/1/2/3 = {codes:?}, slowest {slowest:.1} s CPU");
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    // the generator reaches every outcome the contract names except failures
    assert!(codes[0] > 0 && codes[2] > 0, "{codes:?}");
}

#[test]
#[ignore = "the full study: 10⁴ argument sets, ~10 min on two cores"]
fn every_command_survives_ten_thousand_argument_sets() {
    let (failures, slowest, codes) = campaign(0x5EED_2026, 10_000);
    println!("10⁴ sets: exit codes 0/1/2/3 = {codes:?}, slowest {slowest:.1} s CPU");
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n\n")
    );
}
