//! Timing shared by the benchmarks: two sides run in turns, the median of
//! the per-turn ratios printed.

use std::process::Command;
use std::time::{Duration, Instant};

/// Turns of each comparison.
pub const RUNS: usize = 21;

/// Runs a command to its end; its verdict does not matter here, only that it ran.
pub fn run(command: &mut Command) {
    let status = command
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .unwrap_or_else(|e| panic!("cannot run {command:?}: {e}"));
    std::hint::black_box(status);
}

/// Times `ours` and `theirs` in turns, [`RUNS`] times each after a warm-up
/// run, and prints both medians and the median of the per-turn ratios: a
/// machine that slows down for a while slows both sides of a turn alike.
pub fn compare(what: &str, ours: (&str, &mut dyn FnMut()), theirs: (&str, &mut dyn FnMut())) {
    let (our_name, ours) = ours;
    let (their_name, theirs) = theirs;
    ours();
    theirs();
    let mut turns: Vec<(Duration, Duration)> =
        (0..RUNS).map(|_| (time(ours), time(theirs))).collect();
    let mut ratios: Vec<f64> = turns
        .iter()
        .map(|(o, t)| t.as_secs_f64() / o.as_secs_f64())
        .collect();
    ratios.sort_by(f64::total_cmp);
    let ratio = ratios[RUNS / 2];
    turns.sort_by_key(|(o, _)| *o);
    let our_median = turns[RUNS / 2].0;
    turns.sort_by_key(|(_, t)| *t);
    let their_median = turns[RUNS / 2].1;
    println!(
        "{what}: {our_name} {:.2} ms, {their_name} {:.2} ms (medians of {RUNS}): {our_name} is {ratio:.2}x as fast (median of the ratios, {:.2}x..{:.2}x)",
        our_median.as_secs_f64() * 1e3,
        their_median.as_secs_f64() * 1e3,
        ratios[0],
        ratios[RUNS - 1],
    );
}

fn time(f: &mut dyn FnMut()) -> Duration {
    let start = Instant::now();
    f();
    start.elapsed()
}
