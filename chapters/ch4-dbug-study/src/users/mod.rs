//! The synthetic users of the study: one parameterised model whose traits
//! are drawn per user from the master seed ([`traits`], [`population`]), and
//! the behaviours the chapter describes, each in its own file with the
//! thesis's sentences behind its rates: reading the table ([`perception`]),
//! handling the bugs ([`hands`]), teaching Int-RL ([`reward`]), Behavior
//! Networks ([`kinesthetic`]) and CBA ([`labelling`]), and answering the
//! questionnaire ([`satisfaction`]). The scripted ideal teacher (the
//! thesis's authors) is the same model with [`UserTraits::ideal`] traits and
//! a systematic plan (see `session`).
//!
//! Every constant here is an input to the learners, fixed before any
//! learner ran; none was tuned to move an accuracy or a correlation.

pub mod hands;
pub mod kinesthetic;
pub mod labelling;
pub mod perception;
pub mod population;
pub mod reward;
pub mod satisfaction;
pub mod traits;

use serde::{Deserialize, Serialize};

pub use population::{Algorithm, Roster};
pub use traits::{Expertise, TraitModel, UserTraits};

/// Every constant of the user model, in one place (it is part of every trial's fingerprint).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct UserModel {
    pub traits: TraitModel,
    pub perception: perception::PerceptionModel,
    pub hands: hands::HandsModel,
    pub reward: reward::RewardModel,
    pub kinesthetic: kinesthetic::KinestheticModel,
    pub labelling: labelling::LabellingModel,
    pub satisfaction: satisfaction::SatisfactionModel,
}

impl UserModel {
    /// The study's user model.
    pub const fn thesis() -> UserModel {
        UserModel {
            traits: TraitModel::thesis(),
            perception: perception::PerceptionModel::thesis(),
            hands: hands::HandsModel::thesis(),
            reward: reward::RewardModel::thesis(),
            kinesthetic: kinesthetic::KinestheticModel::thesis(),
            labelling: labelling::LabellingModel::thesis(),
            satisfaction: satisfaction::SatisfactionModel::thesis(),
        }
    }
}
