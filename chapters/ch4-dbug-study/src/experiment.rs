//! The chapter's experiments through the harness: the 31-participant study
//! repeated over independent draws of the users ([`run_study`]), and the
//! scripted ideal teacher on each algorithm ([`run_ideal`]).
//!
//! A study's trial is one participant's hour: their traits, drawn from the
//! trial's seed, and their three sessions in their order. The study's
//! roster (who has which expertise, who uses which order) is drawn from a
//! seed of its own, shared by its 31 trials. Study 0 is the reproduction of
//! the thesis's single study; the others show how much one study of 31
//! varies.

use rlfd_harness::{
    Fingerprint, HarnessError, RunOptions, Scale, TrialKey, TrialPlan, TrialSpec, derive_seed, run_trials,
};
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
    pub computed: usize,
    pub reused: usize,
}

/// Runs (or loads) every study.
pub fn run_study(options: &RunOptions, params: &StudyParams) -> Result<StudyResults, Ch4Error> {
    let params = &StudyParams { learners: params.learners.under(&options.reading), ..params.clone() };
    params.check()?;
    let fingerprint = Fingerprint::new().str(
        &serde_json::to_string(&(&params.session, &params.users, &params.learners)).expect("parameters serialise"),
    );
    let plan = TrialPlan::new(options, crate::CHAPTER_ID, crate::Experiment::Study);
    let plan = &plan;
    let rosters: Vec<Roster> =
        (0..params.studies).map(|s| Roster::draw(&mut seeded(roster_seed(options.master_seed, s)))).collect();
    let specs: Vec<TrialSpec<(u32, u32)>> = (0..params.studies)
        .flat_map(|s| {
            let fp = fingerprint.str(&serde_json::to_string(&rosters[s as usize]).expect("roster serialises"));
            (0..PARTICIPANTS as u32).map(move |p| plan.spec(&format!("study-{s:03}"), p, fp, (s, p)))
        })
        .collect();
    let out = run_trials(options, "dbug study", &specs, |spec| {
        let (s, p) = spec.params;
        run_participant(params, &rosters[s as usize], s, p, spec.seed)
    })?;
    let mut studies: Vec<Vec<ParticipantRecord>> = vec![Vec::new(); params.studies as usize];
    for r in out.results {
        studies[r.study as usize].push(r);
    }
    Ok(StudyResults {
        scale: options.scale,
        seed: options.master_seed,
        params: params.clone(),
        studies,
        computed: out.computed,
        reused: out.reused,
    })
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
    pub computed: usize,
    pub reused: usize,
}

/// Runs (or loads) the scripted ideal teacher on each algorithm.
pub fn run_ideal(options: &RunOptions, params: &IdealParams) -> Result<IdealResults, Ch4Error> {
    let params = &IdealParams { learners: params.learners.under(&options.reading), ..params.clone() };
    check_common(&params.session, &params.learners)?;
    let fingerprint = Fingerprint::new().str(
        &serde_json::to_string(&(&params.session, &params.users, &params.learners)).expect("parameters serialise"),
    );
    let plan = TrialPlan::new(options, crate::CHAPTER_ID, crate::Experiment::IdealTeacher);
    let plan = &plan;
    let specs: Vec<TrialSpec<Algorithm>> = Algorithm::ALL
        .iter()
        .flat_map(|&a| (0..params.trials).map(move |t| plan.spec(a.key(), t, fingerprint, a)))
        .collect();
    let out = run_trials(options, "dbug ideal teacher", &specs, |spec| {
        run_session(
            spec.params,
            &Teacher::ideal(),
            &params.users,
            &params.session,
            &params.learners,
            &mut seeded(spec.seed),
        )
    })?;
    let mut sessions: Vec<Vec<SessionRecord>> = vec![Vec::new(); 3];
    for (spec, r) in specs.iter().zip(out.results) {
        sessions[spec.params.index()].push(r);
    }
    Ok(IdealResults { params: params.clone(), sessions, computed: out.computed, reused: out.reused })
}
