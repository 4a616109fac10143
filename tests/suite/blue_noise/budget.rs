//! Budgets of the blue-noise constructions: a started budget stops every one at its
//! deadline, the estimates keep their measured ranges, and the command ends an admitted
//! run whose cost no estimate bounds within 1.5 times its budget.

use qmckit::Error;
use qmckit::blue_noise::{BestCandidate, GaussianBlueNoise, PoissonDisk};
use qmckit::work::Budget;

/// Runs `job` under a started budget of `seconds` (at least the job's estimate, so it is
/// admitted) after sleeping `1.15 seconds`: the deadline (`1.25 seconds` from the start)
/// falls a tenth of the budget into the job, far before it could finish. The job must stop
/// with [`Error::OutOfTime`] close to the deadline; a loop that never reads the clock runs
/// to its end instead (and a check only on entry passes, since the deadline is still ahead).
pub(crate) fn stops_at_the_deadline<T>(
    what: &str,
    seconds: f64,
    job: impl FnOnce(&Budget) -> qmckit::Result<T>,
) {
    let budget = Budget::seconds(seconds).unwrap().started();
    let start = std::time::Instant::now();
    std::thread::sleep(std::time::Duration::from_secs_f64(1.15 * seconds));
    let got = job(&budget).map(|_| ());
    let took = start.elapsed().as_secs_f64();
    assert!(
        matches!(got, Err(Error::OutOfTime { .. })),
        "{what}: {got:?} after {took:.3} s of a {seconds:.3} s budget"
    );
    // The deadline plus one check interval (milliseconds), with room for a loaded machine.
    assert!(
        took < 1.25 * seconds + 0.25,
        "{what}: stopped {took:.3} s after the start of a {seconds:.3} s budget"
    );
}

/// The smallest of the growing `jobs` whose estimate reaches `seconds` (so the deadline
/// tests run jobs of a fraction of a second whatever the calibration).
fn sized<T: Clone>(jobs: impl IntoIterator<Item = T>, cost: impl Fn(&T) -> f64, seconds: f64) -> T {
    let mut last = None;
    for j in jobs {
        if cost(&j) >= seconds {
            return j;
        }
        last = Some(j);
    }
    last.expect("a job")
}

#[test]
fn every_construction_stops_at_its_deadline() {
    // Poisson disk: 2D tiles (parallel), 2D maximal fill, 3D and 6D sequential loops.
    for (dims, torus, maximal) in [
        (2, true, false),
        (2, false, true),
        (3, true, false),
        (6, false, false),
    ] {
        let pd = sized(
            (1..400).map(|i| {
                PoissonDisk::new(dims, 0.5 * 0.97f64.powi(i))
                    .unwrap()
                    .torus(torus)
                    .maximal(maximal)
            }),
            |pd| pd.cost().unwrap().seconds(),
            0.3,
        );
        let seconds = pd.cost().unwrap().seconds();
        stops_at_the_deadline("Poisson disk", seconds, |b| pd.generate(b));
    }
    let pd = PoissonDisk::with_points(3, 40_000).unwrap();
    stops_at_the_deadline("Poisson disk by count", pd.cost().unwrap().seconds(), |b| {
        pd.generate(b)
    });
    let bc = sized(
        (6..20).map(|m| BestCandidate::new(1 << m).unwrap()),
        |b| b.cost().seconds(),
        0.3,
    );
    stops_at_the_deadline("best candidate", bc.cost().seconds(), |b| bc.generate(b));
    let g = sized(
        (1..1000).map(|i| {
            GaussianBlueNoise::new(1 << 14)
                .unwrap()
                .iterations(i)
                .unwrap()
        }),
        |g| g.cost().seconds(),
        0.3,
    );
    stops_at_the_deadline("Gaussian blue noise", g.cost().seconds(), |b| g.generate(b));
}

#[test]
fn estimates_follow_the_measured_ranges() {
    // What the calibration keeps: more points or candidates cost more, the maximal fill
    // more than Bridson's loop; and the failures of the old model (one point in 8D refused
    // at 670 s, 10^6 points in 2D at 11 s, both measured in seconds) now fit the default.
    let s = |pd: PoissonDisk| pd.cost().unwrap().seconds();
    let r = |d, r| PoissonDisk::new(d, r).unwrap();
    assert!(s(r(2, 0.001)) > 5.0 * s(r(2, 0.003)));
    assert!(s(r(3, 0.02).candidates(300).unwrap()) > 3.0 * s(r(3, 0.02)));
    assert!(s(r(2, 0.01).maximal(true)) > s(r(2, 0.01)));
    assert!(s(PoissonDisk::with_points(8, 1).unwrap()) < 1.0);
    assert!(s(PoissonDisk::with_points(2, 1_000_000).unwrap()) < 10.0);
    // 10^5 points in 5D: measured 6.7 s of CPU (the old model said 1768 s).
    let five = s(PoissonDisk::with_points(5, 100_000).unwrap());
    assert!((3.0..30.0).contains(&five), "{five}");
}
