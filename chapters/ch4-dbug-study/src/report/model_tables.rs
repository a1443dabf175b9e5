//! The user model and the parameters as tables: every chosen value with the
//! thesis sentence it comes from.

use rlfd_report::parameters::Parameters;
use rlfd_report::table::{Cell, ColumnGroup, Row, Table};
use rlfd_report::{Block, Section};

use crate::LearnerParams;
use crate::dbug::TableParams;
use crate::session::SessionParams;
use crate::users::UserModel;

fn three(v: [f64; 3], unit: &str) -> String {
    format!("{}{unit} / {}{unit} / {}{unit}", v[0], v[1], v[2])
}

/// "The user model": traits, behaviours and their sources.
pub fn user_model_section() -> rlfd_report::Result<Section> {
    let m = UserModel::thesis();
    let mut t = Table::new(
        "user_model",
        "The user model: every rate, its value and the thesis's sentence behind it",
        "Behaviour",
    );
    t.caption = "Values per expertise are expert / novice / no background. All were fixed before any learner ran; none was tuned to an accuracy or a correlation. Where the thesis gives a direction but no number, the number is ours.".into();
    t.columns = vec![ColumnGroup::new("Value"), ColumnGroup::new("Thesis")];
    let rows: Vec<(&str, String, &str)> = vec![
        (
            "Expertise",
            "6 / 14 / 11, shuffled per study".into(),
            "\"Six of the participants self-identified as an expert roboticist, while 14 were novice and 11 had no robotics background.\"",
        ),
        ("Orders", "10 Int-RL/BNets/CBA, 10 BNets/CBA/Int-RL, 11 CBA/Int-RL/BNets".into(), "Section 4.3.1."),
        (
            "Reaction time (median, log-normal σ 0.3)",
            three(m.traits.reaction_median, " s"),
            "\"if the teacher is distracted and reacts slowly, corrections may have a negative impact\"",
        ),
        (
            "Attention (median, logit-normal σ 0.6)",
            three(m.traits.attention_median, ""),
            "\"The occurrence of users abandoning rewards before the agent converges\"; assumptions 1–2 of Int-RL \"held\" (most actions get feedback)",
        ),
        (
            "Consistency (median)",
            three(m.traits.consistency_median, ""),
            "\"human teachers often make noisy demonstrations\"; \"noisy demonstrations\" leave Int-RL states tied",
        ),
        (
            "Patience (median, log-normal σ 0.4)",
            three(m.traits.patience_median, " s"),
            "\"led some to stop rewarding or to vary their reward strategy\"; \"people giving up on trial and error process after a few demonstrations\"",
        ),
        (
            "Judged position error",
            three(m.perception.position_error_px, " px"),
            "\"The test subjects were not told how much of the workspace was exactly covered by the camera.\"",
        ),
        (
            "Improvement per earlier session",
            format!("{} of the error", m.perception.familiarity),
            "\"we expected our participants to get better at demonstrating the task over time\"",
        ),
        (
            "Reading of the table (reading table-reading)",
            match m.perception.table_reading {
                crate::users::perception::TableReading::Goal => "every participant: any bug in a zone (the goal)",
                crate::users::perception::TableReading::ExpertsAsRobot => {
                    "experts: the bug nearest the mark (the robot's state); others: any bug in a zone"
                }
            }
            .into(),
            "users aimed at \"the ultimate goal of sweeping and picking-up hexbugs\" (l. 582); \"it was hard for most users to realize which behavior was activated when\" (l. 580)",
        ),
        (
            "Int-RL and CBA: controls the bugs in a session",
            three(m.hands.control_probability, ""),
            "\"often met unintentionally if the user did not control the location of the hexbugs (e.g., by turning them off and displacing them manually)\"",
        ),
        (
            "Moves a roaming bug into a zone",
            format!("every {} s with probability {}", m.hands.nudge_seconds, m.hands.nudge_probability),
            "\"The test subject had the option of turning the hexbugs on and off, or moving them around at will.\"",
        ),
        (
            "Int-RL: reward a watched action",
            "+1 if judged right, −1 if wrong".into(),
            "\"A positive feedback will follow most correct actions\", \"A negative feedback will follow most incorrect actions\"",
        ),
        (
            "Int-RL: guide before an action",
            format!("attention × {}: one action judged wrong taken out", m.reward.guide_probability),
            "\"Guidance will be given in order to narrow down the choice\"; \"the user cannot give a specific action command\"",
        ),
        (
            "Int-RL: strategy change",
            format!(
                "no progress over a patience period: stop (p = {}) or reward only right actions",
                m.reward.stop_probability
            ),
            "\"Many users could not see an improvement … which led some to stop rewarding or to vary their reward strategy\"",
        ),
        (
            "BNets: controls the bugs (reading bnets-bug-control)",
            format!(
                "{:.2} of the participants, whatever the expertise; after START, bugs switched off where they stand and one displaced into the pick-up or sweep zone (nothing cleared)",
                m.kinesthetic.bug_control.share()
            ),
            "\"often met unintentionally if the user did not control the location of the hexbugs (e.g., by turning them off and displacing them manually)\" (l. 580)",
        ),
        (
            "BNets: both arms at once (reading bnets-both-arms)",
            match m.kinesthetic.both_arms {
                crate::users::kinesthetic::BothArms::WithSweep => "every participant, the pick-up arm with every sweep; a habit kept through erasing",
                crate::users::kinesthetic::BothArms::HalfTheUsers => "half the participants, the pick-up arm with every sweep",
                crate::users::kinesthetic::BothArms::EveryDemonstration => "every participant, both arms in every motion",
            }
            .into(),
            "\"executing a pickup action after every sweep … Similar unintended dependencies were taught by every user\" (l. 582); \"Even when they erased … they moved both arms at the same time\" (l. 606)",
        ),
        (
            "BNets: motions per demonstration",
            format!("1 to {}", m.kinesthetic.max_motions),
            "\"performing one or more actions through kinesthetic teaching\"",
        ),
        (
            "BNets: erase before re-teaching",
            three(m.kinesthetic.erase_probability, ""),
            "\"users tried to erase and re-teach the task multiple times\"",
        ),
        (
            "BNets: watch after a demonstration",
            format!("{} s; satisfied at {} judged right", m.kinesthetic.watch_seconds, m.kinesthetic.satisfied_share),
            "\"explored the behavior of the algorithm through trial and error\"",
        ),
        (
            "BNets: the authors' demonstrations (scripted ideal teacher only)",
            "one for pick-up, one for sweep; before each START the table cleared and one bug placed, switched off, in the zone".into(),
            "\"could teach the task with only two demonstrations (one for pick-up and one of sweep) by controlling the location of hexbugs manually\"",
        ),
        (
            "CBA: answer a request",
            format!("reaction time, plus a lapse of mean {} s when not watching", m.labelling.lapse_seconds),
            "\"the environment did not pause when the robot requested help\"",
        ),
        (
            "CBA: correct a watched mistake",
            format!(
                "after recognising it, reaction time + {} s; late ones label the next state",
                m.labelling.correction_seconds
            ),
            "\"Several users also violated assumption (2) by not providing corrections within the required timeframe\"",
        ),
        (
            "Satisfaction (reading satisfaction-form)",
            format!(
                "second half of the session; {}; noise σ {}",
                match m.satisfaction.form {
                    crate::users::satisfaction::SatisfactionForm::PickupCount =>
                        "one point per bug seen picked up, up to the three on the table".to_string(),
                    crate::users::satisfaction::SatisfactionForm::SuccessCount =>
                        "one point per pick-up or sweep judged right, up to three".to_string(),
                    crate::users::satisfaction::SatisfactionForm::Ratio => format!(
                        "share judged right, waits weigh {}, a lifted bug {} more",
                        m.satisfaction.wait_weight, m.satisfaction.lift_bonus
                    ),
                },
                m.satisfaction.noise
            ),
            "\"users evaluated performance based on the success of picking up as many hexbugs as possible\"",
        ),
        (
            "Scripted ideal teacher",
            "reaction 0.3 s, attention 1, consistency 1, a systematic plan per algorithm".into(),
            "\"the authors … were able to teach the task using all three methods within this time frame\"",
        ),
    ];
    for (name, value, source) in rows {
        t.rows.push(Row::new(name, vec![Cell::text(value), Cell::text(source)]));
    }
    t.check()?;
    Ok(Section::new(
        "The user model",
        vec![
            Block::paragraph(
                "One parameterised model; each user's traits are drawn from the master seed, and each behaviour's rate follows from the traits. The scattered CBA demonstrations, the users with too few of them, the late corrections and the unintended BNets preconditions are not rates of the model: they follow from where the bugs are when the user acts.",
            ),
            Block::Table(t),
        ],
    ))
}

/// The chapter's parameters.
pub fn parameters_table() -> rlfd_report::Result<Table> {
    let s = SessionParams::thesis();
    let l = LearnerParams::thesis();
    let tp = TableParams::thesis();
    let mut rows = Parameters::new("dbug_parameters", "DBug parameters");
    rows.thesis_says("Session length", format!("{} s", s.seconds), "{ch4.session_minutes} minutes");
    rows.thesis("Image", "320 × 240, 76,800 states");
    rows.thesis("Action durations", "pick-up 9 s, sweep 5 s, wait 1 s");
    rows.thesis("Table", format!("{}\" × {}\", 3 bugs", tp.width, tp.height));
    rows.row(
        "Bug speed, back-up",
        format!("{} in/s; {} in/s for {} s", tp.bug.speed, tp.bug.backup_speed, tp.bug.backup_seconds),
        "our choice",
    );
    rows.row(
        "Perception pause before each action",
        format!("{} s", s.decision_gap_seconds),
        "our choice (reading decision-gap)",
    );
    rows.row(
        "CBA pause for corrections",
        format!("{} s", s.correction_pause_seconds),
        "our choice (\"added small wait commands\")",
    );
    rows.row("Int-RL credit delay", format!("{} s", s.credit_delay_seconds), "our choice (reading intrl-credit-delay)");
    rows.row("Time a controlling user leaves a spot", format!("{} s", s.dwell_seconds), "our choice");
    rows.thesis("Int-RL grid", "10 × 10 (32 × 24 px)");
    rows.thesis("Int-RL Q0, α, γ", format!("{}, {}, {}", l.intrl.q0, l.intrl.alpha, l.intrl.gamma));
    rows.row("Int-RL ε", l.intrl.epsilon, "chapter 3's initial ε, held constant (reading intrl-epsilon)");
    rows.thesis("CBA minimum demonstrations per action", l.cba.min_demonstrations);
    rows.row("CBA components per action", format!("1 to {} (BIC)", l.cba.max_components), "our choice");
    rows.row("CBA covariance floor", format!("{} px²", l.cba.em.reg_covar), "our choice");
    rows.row(
        "CBA distance threshold",
        format!("{} × mean nearest-neighbour distance", l.cba.distance_factor),
        "Chernova & Veloso 2009",
    );
    rows.row(
        "CBA confidence threshold",
        "mean confidence of misclassified training points per boundary",
        "Chernova & Veloso 2009",
    );
    rows.row("BNets arm effect hold", "1 s", "our choice");
    rows.table()
}
