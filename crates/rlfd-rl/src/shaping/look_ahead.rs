//! Look-ahead advice: static potential-based shaping over state-action pairs
//! (Wiewiora, Cottrell & Elkan 2003).

use super::{Selection, Shaping, StateActionFunction, Transition, Visit, potential_difference};

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
}

impl<P: StateActionFunction> LookAheadShaping<P> {
    /// Advice from `potential`, multiplied by `scale`.
    pub fn new(potential: P, scale: f64, selection: Selection) -> Self {
        LookAheadShaping { potential, scale, selection }
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
        potential_difference(t)
    }
}
