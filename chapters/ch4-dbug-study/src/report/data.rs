//! Chapter 4's data files, one typed row per session written by the `csv`
//! crate: `dbug_users.csv` (every user and algorithm of every study) and
//! `ideal_teacher_sessions.csv` (every session of the scripted ideal
//! teacher).
//!
//! Both files end with the same per-algorithm detail columns (empty where a
//! column does not apply to the session's algorithm). The `csv` crate writes
//! a header only for a flat struct (no nested struct, no `serde(flatten)`),
//! so each row serialises its own fields and then the shared ones through
//! [`session_fields`] and [`detail_fields`]: every column is named once.

use rlfd_report::data_file::csv_of;
use serde::ser::{Serialize, SerializeStruct, Serializer};

use crate::dbug::Zone;
use crate::experiment::ParticipantRecord;
use crate::session::{Details, SessionRecord};
use crate::users::Algorithm;
use crate::{IdealResults, StudyResults};

/// `dbug_users.csv`: one row per user and algorithm, over every study.
pub(super) fn users_csv(r: &StudyResults) -> Vec<u8> {
    csv_of(
        r.studies
            .iter()
            .flatten()
            .flat_map(|participant| Algorithm::ALL.map(|algorithm| UserRow { participant, algorithm })),
    )
}

/// `ideal_teacher_sessions.csv`: every session of the scripted ideal teacher
/// (its table and C4.9 come from it).
pub(super) fn ideal_csv(i: &IdealResults) -> Vec<u8> {
    csv_of(Algorithm::ALL.into_iter().flat_map(|algorithm| {
        i.sessions[algorithm.index()].iter().enumerate().map(move |(session, record)| IdealRow {
            algorithm,
            session,
            record,
        })
    }))
}

/// One user's session with one algorithm.
struct UserRow<'a> {
    participant: &'a ParticipantRecord,
    algorithm: Algorithm,
}

impl Serialize for UserRow<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let (p, a) = (self.participant, self.algorithm);
        let x = p.session(a);
        let order: Vec<&str> = p.order.iter().map(|a| a.key()).collect();
        let position = p.order.iter().position(|&o| o == a).unwrap_or(0) + 1;
        let mut s = serializer.serialize_struct("UserRow", 18 + DETAIL_COLUMNS)?;
        s.serialize_field("study", &p.study)?;
        s.serialize_field("user", &p.participant)?;
        s.serialize_field("expertise", p.traits.expertise.label())?;
        s.serialize_field("reaction_time_s", &p.traits.reaction_time)?;
        s.serialize_field("attention", &p.traits.attention)?;
        s.serialize_field("consistency", &p.traits.consistency)?;
        s.serialize_field("patience_s", &p.traits.patience)?;
        s.serialize_field("order", &order.join("/"))?;
        s.serialize_field("algorithm", a.key())?;
        s.serialize_field("position_in_order", &position)?;
        session_fields(&mut s, x)?;
        s.serialize_field("satisfaction", &x.satisfaction)?;
        s.serialize_field("controlled_bugs", &x.controlled)?;
        s.serialize_field("hand_moves", &x.hand_moves)?;
        detail_fields(&mut s, &x.details)?;
        s.end()
    }
}

/// One session of the scripted ideal teacher.
struct IdealRow<'a> {
    algorithm: Algorithm,
    session: usize,
    record: &'a SessionRecord,
}

impl Serialize for IdealRow<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut s = serializer.serialize_struct("IdealRow", 7 + DETAIL_COLUMNS)?;
        s.serialize_field("algorithm", self.algorithm.key())?;
        s.serialize_field("session", &self.session)?;
        session_fields(&mut s, self.record)?;
        detail_fields(&mut s, &self.record.details)?;
        s.end()
    }
}

/// Accuracy overall and per zone (%), and interactions.
fn session_fields<S: SerializeStruct>(s: &mut S, x: &SessionRecord) -> Result<(), S::Error> {
    s.serialize_field("accuracy", &x.accuracy.overall)?;
    s.serialize_field("pickup_zone", &x.accuracy.zone(Zone::Pickup))?;
    s.serialize_field("sweep_zone", &x.accuracy.zone(Zone::Sweep))?;
    s.serialize_field("wait_zone", &x.accuracy.zone(Zone::Wait))?;
    s.serialize_field("interactions", &x.interactions)
}

/// The number of [`detail_fields`] columns.
const DETAIL_COLUMNS: usize = 17;

/// The per-algorithm details every observation of the chapter is counted
/// from: Int-RL's untied cells and reward-strategy changes; BNets' branches,
/// erasures, both-arm demonstrations and giving up; CBA's classifier (and
/// its Gaussians), demonstrations per action, requests, corrections, late
/// corrections, autonomous actions, unanswered requests and giving up.
fn detail_fields<S: SerializeStruct>(s: &mut S, d: &Details) -> Result<(), S::Error> {
    let (mut intrl, mut bnets, mut cba) = (None, None, None);
    match d {
        Details::IntRl { untied, strategy_changes, .. } => intrl = Some((*untied, *strategy_changes)),
        Details::BNets { branches, erasures, both_arms, gave_up, .. } => {
            bnets = Some((branches.len(), *erasures, *both_arms, *gave_up))
        }
        Details::Cba {
            classifier,
            counts,
            requests,
            corrections,
            late_corrections,
            autonomous,
            unanswered,
            gave_up,
        } => {
            cba = Some((
                classifier,
                counts,
                [*requests, *corrections, *late_corrections, *autonomous, *unanswered],
                *gave_up,
            ))
        }
    }
    s.serialize_field("intrl_untied_cells", &intrl.map(|x| x.0))?;
    s.serialize_field("intrl_strategy_changes", &intrl.map(|x| x.1))?;
    s.serialize_field("bnets_branches", &bnets.map(|x| x.0))?;
    s.serialize_field("bnets_erasures", &bnets.map(|x| x.1))?;
    s.serialize_field("bnets_both_arms", &bnets.map(|x| x.2))?;
    s.serialize_field("bnets_gave_up", &bnets.map(|x| x.3))?;
    s.serialize_field("cba_classifier", &cba.map(|x| x.0.is_some()))?;
    let gaussians = cba.and_then(|x| x.0.as_ref()).map(|c| c.models.iter().map(|g| g.components.len()).sum::<usize>());
    s.serialize_field("cba_gaussians", &gaussians)?;
    s.serialize_field("cba_demos_pickup", &cba.map(|x| x.1[0]))?;
    s.serialize_field("cba_demos_sweep", &cba.map(|x| x.1[1]))?;
    s.serialize_field("cba_demos_wait", &cba.map(|x| x.1[2]))?;
    s.serialize_field("cba_requests", &cba.map(|x| x.2[0]))?;
    s.serialize_field("cba_corrections", &cba.map(|x| x.2[1]))?;
    s.serialize_field("cba_late_corrections", &cba.map(|x| x.2[2]))?;
    s.serialize_field("cba_autonomous", &cba.map(|x| x.2[3]))?;
    s.serialize_field("cba_unanswered", &cba.map(|x| x.2[4]))?;
    s.serialize_field("cba_gave_up", &cba.map(|x| x.3))
}
