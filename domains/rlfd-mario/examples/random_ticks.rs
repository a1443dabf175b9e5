//! Plays `ticks` ticks of random actions on the experiment's levels (the
//! `cargo xtask bench` simulator workload), for profiling:
//! `valgrind --tool=callgrind target/release/examples/random_ticks 7 300000`.

fn main() {
    let mut args = std::env::args().skip(1);
    let parse = |a: Option<String>, default: u64| match a {
        None => Ok(default),
        Some(s) => s.parse::<u64>().map_err(|_| format!("not a whole number: {s}")),
    };
    let mut run = || -> Result<u64, String> {
        let seed = parse(args.next(), 7)?;
        let ticks = parse(args.next(), 300_000)?;
        Ok(rlfd_mario::random_ticks(seed, ticks))
    };
    match run() {
        Ok(n) => println!("{n} ticks"),
        Err(e) => {
            eprintln!("error: {e} (usage: random_ticks [SEED] [TICKS])");
            std::process::exit(2);
        }
    }
}
