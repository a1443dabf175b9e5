//! The chapter's experiments through the harness: the 31-participant study
//! repeated over independent draws of the users ([`plan_study`]), and the
//! scripted ideal teacher on each algorithm ([`plan_ideal`]).
//!
//! A study's trial is one participant's hour: their traits, drawn from the
//! trial's seed, and their three sessions in their order. The study's
//! roster (who has which expertise, who uses which order) is drawn from a
//! seed of its own, shared by its 31 trials. Study 0 is the reproduction of
//! the thesis's single study; the others show how much one study of 31
//! varies.

use rlfd_harness::{Batch, HarnessError, RunContext, RunOptions, Scale, TrialKey, TrialRunner, derive_seed};
use rlfd_rl::random::seeded;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::session::{SessionParams, SessionRecord, Teacher, run_session};
use crate::users::population::PARTICIPANTS;
use crate::users::{Algorithm, Roster, UserModel, UserTraits};
use crate::{CHAPTER, LearnerParams};

/// The study's name on the command line and in result paths.
pub const STUDY: &str = crate::Experiment::Study.name();
/// The ideal teacher's experiment.
pub const IDEAL: &str = crate::Experiment::IdealTeacher.name();

/// What can stop the chapter.
#[derive(Debug, Error)]
pub enum Ch4Error {
    /// Storing or loading trials failed.
    #[error(transparent)]
    Harness(#[from] HarnessError),
    /// Parameters that cannot run.
    #[error("invalid chapter 4 parameters: {0}")]
    Params(String),
}

/// The study's parameters.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StudyParams {
    /// Independent studies of 31 participants (paper: 100; study 0 is the reproduction).
    pub studies: u32,
    pub session: SessionParams,
    pub users: UserModel,
    pub learners: LearnerParams,
}

impl StudyParams {
    /// 100 studies of 31 participants, ten-minute sessions.
    pub fn paper() -> StudyParams {
        StudyParams {
            studies: 100,
            session: SessionParams::thesis(),
            users: UserModel::thesis(),
            learners: LearnerParams::thesis(),
        }
    }

    /// Every code path in seconds: 3 studies.
    pub fn quick() -> StudyParams {
        StudyParams { studies: 3, ..StudyParams::paper() }
    }

    /// The parameters of a scale.
    pub fn for_scale(scale: Scale) -> StudyParams {
        match scale {
            Scale::Quick => StudyParams::quick(),
            Scale::Paper => StudyParams::paper(),
        }
    }

    /// Checks what the sessions assume.
    pub fn check(&self) -> Result<(), Ch4Error> {
        check_common(&self.session, &self.learners)?;
        if self.studies == 0 {
            return Err(Ch4Error::Params("at least one study is needed".into()));
        }
        Ok(())
    }
}

fn check_common(s: &SessionParams, l: &LearnerParams) -> Result<(), Ch4Error> {
    let bad = |m: &str| Err(Ch4Error::Params(m.into()));
    if !(s.seconds > 0.0 && s.seconds <= 3600.0) {
        return bad("session length must be in (0, 3600] seconds");
    }
    if !(s.decision_gap_seconds >= 0.0 && s.correction_pause_seconds >= 0.0 && s.credit_delay_seconds >= 0.0) {
        return bad("pauses and delays must not be negative");
    }
    let i = &l.intrl;
    if !(i.alpha > 0.0 && i.alpha <= 1.0 && (0.0..1.0).contains(&i.gamma) && (0.0..=1.0).contains(&i.epsilon)) {
        return bad("Int-RL needs 0 < α ≤ 1, 0 ≤ γ < 1, 0 ≤ ε ≤ 1");
    }
    let c = &l.cba;
    if c.min_demonstrations == 0 || c.max_components == 0 || c.em.reg_covar.is_nan() || c.em.reg_covar <= 0.0 {
        return bad("CBA needs at least one demonstration and component per action and a positive covariance floor");
    }
    Ok(())
}

/// One participant's hour.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ParticipantRecord {
    pub study: u32,
    pub participant: u32,
    pub traits: UserTraits,
    pub order: [Algorithm; 3],
    /// The sessions in [`Algorithm::ALL`] order (whatever order they ran in).
    pub sessions: Vec<SessionRecord>,
}

impl ParticipantRecord {
    /// The session of one algorithm.
    pub fn session(&self, a: Algorithm) -> &SessionRecord {
        &self.sessions[a.index()]
    }
}

/// The seed of a study's roster.
pub fn roster_seed(master: u64, study: u32) -> u64 {
    derive_seed(master, &TrialKey::new(CHAPTER, STUDY, "roster", study))
}

/// Runs one participant's three sessions.
pub fn run_participant(
    params: &StudyParams,
    roster: &Roster,
    study: u32,
    participant: u32,
    seed: u64,
) -> ParticipantRecord {
    let mut rng = seeded(seed);
    let k = participant as usize;
    let traits = params.users.traits.draw(roster.expertise[k], &mut rng);
    let order = roster.orders[k];
    let mut sessions: Vec<Option<SessionRecord>> = vec![None, None, None];
    for (n, &a) in order.iter().enumerate() {
        let teacher = Teacher { traits, session: n, ideal: false };
        sessions[a.index()] =
            Some(run_session(a, &teacher, &params.users, &params.session, &params.learners, &mut rng));
    }
    ParticipantRecord {
        study,
        participant,
        traits,
        order,
        sessions: sessions.into_iter().map(|s| s.expect("every algorithm ran")).collect(),
    }
}

/// The study's results.
#[derive(Clone, Debug)]
pub struct StudyResults {
    pub scale: Scale,
    pub seed: u64,
    pub params: StudyParams,
    /// Per study, its participants in order.
    pub studies: Vec<Vec<ParticipantRecord>>,
}

/// The study's trials: each study's roster is the set-up (drawn from a seed
/// of its own), each participant a trial `(study, participant)`.
#[derive(Clone, Debug, Serialize)]
pub struct StudyTrials {
    /// The master seed the rosters are drawn from.
    pub master_seed: u64,
    /// The study's parameters under the run's reading.
    pub params: StudyParams,
}

impl TrialRunner for StudyTrials {
    type Setup = Vec<Roster>;
    type Params = (u32, u32);
    type Result = ParticipantRecord;
    type Error = Ch4Error;

    fn setup(&self) -> Result<Vec<Roster>, Ch4Error> {
        Ok((0..self.params.studies).map(|s| Roster::draw(&mut seeded(roster_seed(self.master_seed, s)))).collect())
    }

    fn run(&self, rosters: &Vec<Roster>, &(s, p): &(u32, u32), seed: u64) -> ParticipantRecord {
        run_participant(&self.params, &rosters[s as usize], s, p, seed)
    }
}

/// Plans every study: `params` with the run's reading of the learners, the users and the session.
pub fn plan_study(ctx: &RunContext, params: &StudyParams) -> Result<Batch<StudyTrials>, Ch4Error> {
    let params = StudyParams {
        learners: params.learners.under(&ctx.reading),
        users: params.users.under(&ctx.reading),
        session: params.session.under(&ctx.reading),
        ..params.clone()
    };
    params.check()?;
    let studies = params.studies;
    let mut batch =
        Batch::new(ctx, CHAPTER, crate::Experiment::Study, StudyTrials { master_seed: ctx.master_seed, params });
    for s in 0..studies {
        for p in 0..PARTICIPANTS as u32 {
            batch.trial(&format!("study-{s:03}"), p, (s, p));
        }
    }
    Ok(batch)
}

/// Runs (or loads) every study of `batch`.
pub fn run_study(batch: &Batch<StudyTrials>, options: &RunOptions) -> Result<StudyResults, Ch4Error> {
    let params = batch.runner().params.clone();
    let out = batch.execute(options)?;
    let mut studies: Vec<Vec<ParticipantRecord>> = vec![Vec::new(); params.studies as usize];
    for r in out.results {
        studies[r.study as usize].push(r);
    }
    Ok(StudyResults { scale: batch.scale, seed: batch.master_seed, params, studies })
}

/// The ideal teacher's parameters.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct IdealParams {
    /// Sessions per algorithm (paper: 10).
    pub trials: u32,
    pub session: SessionParams,
    pub users: UserModel,
    pub learners: LearnerParams,
}

impl IdealParams {
    /// Ten sessions per algorithm.
    pub fn paper() -> IdealParams {
        IdealParams {
            trials: 10,
            session: SessionParams::thesis(),
            users: UserModel::thesis(),
            learners: LearnerParams::thesis(),
        }
    }

    /// Two sessions per algorithm.
    pub fn quick() -> IdealParams {
        IdealParams { trials: 2, ..IdealParams::paper() }
    }

    /// The parameters of a scale.
    pub fn for_scale(scale: Scale) -> IdealParams {
        match scale {
            Scale::Quick => IdealParams::quick(),
            Scale::Paper => IdealParams::paper(),
        }
    }
}

/// The ideal teacher's sessions.
#[derive(Clone, Debug)]
pub struct IdealResults {
    pub params: IdealParams,
    /// Per algorithm ([`Algorithm::ALL`] order), its sessions.
    pub sessions: Vec<Vec<SessionRecord>>,
}

/// The ideal teacher's trials: one session of an algorithm each.
#[derive(Clone, Debug, Serialize)]
pub struct IdealTrials {
    /// Its parameters under the run's reading.
    pub params: IdealParams,
}

impl TrialRunner for IdealTrials {
    type Setup = ();
    type Params = Algorithm;
    type Result = SessionRecord;
    type Error = Ch4Error;

    fn setup(&self) -> Result<(), Ch4Error> {
        Ok(())
    }

    fn run(&self, _: &(), &a: &Algorithm, seed: u64) -> SessionRecord {
        let p = &self.params;
        run_session(a, &Teacher::ideal(), &p.users, &p.session, &p.learners, &mut seeded(seed))
    }
}

/// Plans the scripted ideal teacher on each algorithm.
pub fn plan_ideal(ctx: &RunContext, params: &IdealParams) -> Result<Batch<IdealTrials>, Ch4Error> {
    let params = IdealParams {
        learners: params.learners.under(&ctx.reading),
        users: params.users.under(&ctx.reading),
        session: params.session.under(&ctx.reading),
        ..params.clone()
    };
    check_common(&params.session, &params.learners)?;
    let trials = params.trials;
    let mut batch = Batch::new(ctx, CHAPTER, crate::Experiment::IdealTeacher, IdealTrials { params });
    for a in Algorithm::ALL {
        for t in 0..trials {
            batch.trial(a.key(), t, a);
        }
    }
    Ok(batch)
}

/// Runs (or loads) the scripted ideal teacher's sessions of `batch`.
pub fn run_ideal(batch: &Batch<IdealTrials>, options: &RunOptions) -> Result<IdealResults, Ch4Error> {
    let out = batch.execute(options)?;
    let mut sessions: Vec<Vec<SessionRecord>> = vec![Vec::new(); 3];
    for (t, r) in batch.trials().iter().zip(out.results) {
        sessions[t.params.index()].push(r);
    }
    Ok(IdealResults { params: batch.runner().params.clone(), sessions })
}
