//! Static potential-based shaping over states (Ng et al. 1999; the thesis's SIS).

use super::{Shaping, StateFunction, TerminalPotential, Transition, Visit, potential_difference};

/// `F = scale · (γΦ(s') − Φ(s))` for a fixed state potential `Φ`.
#[derive(Clone, Debug)]
pub struct StaticShaping<P> {
    potential: P,
    scale: f64,
    terminal: TerminalPotential,
}

impl<P: StateFunction> StaticShaping<P> {
    /// Shaping from `potential`, multiplied by `scale`.
    pub fn new(potential: P, scale: f64) -> Self {
        StaticShaping { potential, scale, terminal: TerminalPotential::Zero }
    }

    /// The same shaping with the given potential at terminal states.
    pub fn with_terminal(self, terminal: TerminalPotential) -> Self {
        StaticShaping { terminal, ..self }
    }

    /// The potential function.
    pub fn potential(&self) -> &P {
        &self.potential
    }
}

impl<P: StateFunction> Shaping for StaticShaping<P> {
    #[inline]
    fn biases_selection(&self) -> bool {
        // A state potential adds the same amount to every action: it cannot
        // change the greedy action, so there is nothing to correct.
        false
    }

    #[inline]
    fn potentials(&mut self, visit: &Visit<'_>, out: &mut [f64]) {
        out.fill(self.scale * self.potential.value(visit.state));
    }

    #[inline]
    fn reward(&mut self, t: &Transition<'_>) -> f64 {
        match self.terminal {
            TerminalPotential::Zero => potential_difference(t, |_| 0.0),
            TerminalPotential::Literal => potential_difference(t, |s| self.scale * self.potential.value(s)),
        }
    }
}
