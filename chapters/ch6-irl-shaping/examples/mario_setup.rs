//! Times the Mario experiment's setup (demonstrations, RE-IRL, RIPPER, SBS)
//! and prints what it produced: `cargo run --release -p ch6-irl-shaping --example mario_setup`.

fn main() {
    let t = std::time::Instant::now();
    let params = ch6_irl_shaping::mario::params::MarioParams::quick();
    let demos = ch6_irl_shaping::mario::experiment::demonstrations(20160501, &params);
    println!("demonstrations: {:?} ({:.1} s)", demos.stats, t.elapsed().as_secs_f64());
    let t = std::time::Instant::now();
    let inputs = ch6_irl_shaping::mario::inputs::prepare(20160501, &params, &demos.set).unwrap();
    println!(
        "prepare: {:.1} s; horizon {}; theta {:?}; converged {} after {} iterations, on bound {}, stability {:e}, residual {:e}",
        t.elapsed().as_secs_f64(),
        inputs.irl.horizon,
        inputs.irl.fit.scaled_weights,
        inputs.irl.fit.converged,
        inputs.irl.fit.iterations,
        inputs.irl.fit.on_bound,
        inputs.irl.fit.stability,
        inputs.irl.fit.residual
    );
    println!(
        "rules ({} , accuracy {:.3}):\n{}",
        inputs.agents.rules.rules.len(),
        inputs.rules_accuracy,
        inputs.agents.rules
    );
}
