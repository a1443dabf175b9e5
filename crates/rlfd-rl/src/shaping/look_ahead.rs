//! Look-ahead advice: static potential-based shaping over state-action pairs
//! (Wiewiora, Cottrell & Elkan 2003).

use super::{Selection, Shaping, StateActionFunction, TerminalPotential, Transition, Visit, potential_difference};

/// `F = scale · (γΦ(s', a') − Φ(s, a))` for a fixed state-action potential.
///
/// With [`Selection::Corrected`] the agent acts greedily on `Q + scale·Φ`: the
/// learned values converge to `Q* − scale·Φ`, so this restores the greedy
/// policy, and it makes the agent behave exactly like one whose action values
/// start at `scale·Φ` (Q-initialisation).
#[derive(Clone, Debug)]
pub struct LookAheadShaping<P> {
    potential: P,
    scale: f64,
    selection: Selection,
    terminal: TerminalPotential,
    /// Φ(terminal, ·) for the literal reading (allocated once).
    scratch: Vec<f64>,
}

impl<P: StateActionFunction> LookAheadShaping<P> {
    /// Advice from `potential`, multiplied by `scale`.
    pub fn new(potential: P, scale: f64, selection: Selection) -> Self {
        LookAheadShaping { potential, scale, selection, terminal: TerminalPotential::Zero, scratch: Vec::new() }
    }

    /// The same advice with the given potential at terminal states (the
    /// literal reading needs `actions` values of scratch space).
    pub fn with_terminal(self, terminal: TerminalPotential, actions: usize) -> Self {
        LookAheadShaping { terminal, scratch: vec![0.0; actions], ..self }
    }

    /// The potential function.
    pub fn potential(&self) -> &P {
        &self.potential
    }
}

impl<P: StateActionFunction> Shaping for LookAheadShaping<P> {
    #[inline]
    fn biases_selection(&self) -> bool {
        self.selection == Selection::Corrected
    }

    #[inline]
    fn potentials(&mut self, visit: &Visit<'_>, out: &mut [f64]) {
        self.potential.values(visit.state, out);
        for v in out.iter_mut() {
            *v *= self.scale;
        }
    }

    #[inline]
    fn reward(&mut self, t: &Transition<'_>) -> f64 {
        match self.terminal {
            TerminalPotential::Zero => potential_difference(t, |_| 0.0),
            TerminalPotential::Literal => {
                let (potential, scratch, scale) = (&self.potential, &mut self.scratch, self.scale);
                potential_difference(t, |s| {
                    potential.values(s, scratch);
                    scale * scratch.iter().copied().fold(f64::NEG_INFINITY, f64::max)
                })
            }
        }
    }
}
