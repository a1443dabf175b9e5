//! The Python classes and functions of `rlfd._rlfd`: thin adapters from
//! NumPy arrays and Python values to the workspace's crates and back.
//!
//! Every argument is checked here or by the crate's own checks before any
//! work is done, and a refused one raises `ValueError` (or `TypeError` for a
//! value of the wrong kind) with the crate's one-line message. Every entry
//! point also runs inside [`guarded`], so a broken invariant deep in a crate
//! (a panic, which checked input should never reach) becomes a Python
//! `RuntimeError` naming the call instead of unwinding into the interpreter.
//!
//! The pure-Python package `rlfd` (Gymnasium environments, wrappers, the
//! documented API) is built on these; users are not expected to call them
//! directly.

use std::panic::{AssertUnwindSafe, catch_unwind};

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString};
use rlfd_env::demonstration::{DemonstrationSet, Format, Trajectory};
use rlfd_env::random::{SimRng, seeded};
use rlfd_keepaway::BenchmarkPolicy;
use rlfd_lfd::irl::{
    IrlError, IrlFeatureScale, LinearReward, Normalisation, RelativeEntropyIrl, RelativeEntropyIrlParams,
    StateVariables, Stopping, Tolerance, feature_counts,
};
use rlfd_lfd::ripper::{
    Attribute, AttributeKind, Dataset, DecisionList, ErrorRateCheck, Operator, Pruning, Ripper, RipperParams,
    RipperRandom, stratified_cross_validation,
};
use rlfd_lfd::similarity::SimilarityPotential;
use rlfd_rl::features::{ActiveFeatures, FeatureMap, TileCoder, TileIndexing};
use rlfd_rl::shaping::{
    DynamicShaping, Next, Selection, Shaping, StateActionFunction, StateFunction, Transition, Visit,
};

use crate::domain::{Domain, DomainSpec, OptionValue};
use crate::render::render;
use crate::vector::VectorDomain;

/// Runs `f`, turning a panic into a `RuntimeError` that names `what`.
pub fn guarded<T>(what: &str, f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(result) => result,
        Err(payload) => {
            let message = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            Err(PyRuntimeError::new_err(format!("{what}: internal error (please report it): {message}")))
        }
    }
}

fn value_error(message: impl Into<String>) -> PyErr {
    PyValueError::new_err(message.into())
}

/// Reads a `dict` of environment options into (name, value) pairs.
fn options_of(options: Option<&Bound<'_, PyDict>>) -> PyResult<Vec<(String, OptionValue)>> {
    let mut out = Vec::new();
    let Some(options) = options else { return Ok(out) };
    for (key, value) in options.iter() {
        let name: String =
            key.extract().map_err(|_| PyTypeError::new_err(format!("option names must be strings, got {key}")))?;
        let value = if value.is_none() {
            OptionValue::None
        } else if value.is_instance_of::<PyBool>() {
            OptionValue::Other(value.repr()?.to_string())
        } else if value.is_instance_of::<PyInt>() || value.hasattr("__index__")? && !value.is_instance_of::<PyFloat>() {
            match value.extract::<i64>() {
                Ok(v) => OptionValue::Int(v),
                Err(_) => OptionValue::Other(value.repr()?.to_string()),
            }
        } else if value.is_instance_of::<PyFloat>() {
            OptionValue::Float(value.extract()?)
        } else if value.is_instance_of::<PyString>() {
            OptionValue::Str(value.extract()?)
        } else {
            OptionValue::Other(value.repr()?.to_string())
        };
        out.push((name, value));
    }
    Ok(out)
}

fn spec_of(domain: &str, options: Option<&Bound<'_, PyDict>>) -> PyResult<DomainSpec> {
    DomainSpec::parse(domain, &options_of(options)?).map_err(value_error)
}

/// One state or observation argument: anything NumPy reads as a 1-D array
/// of `dim` finite numbers (a float32 array or a list too), else
/// `TypeError`/`ValueError` with one sentence saying what was expected.
fn state_arg(obj: &Bound<'_, PyAny>, dim: usize, what: &str) -> PyResult<Vec<f64>> {
    let values: Vec<f64> = if let Ok(a) = obj.extract::<PyReadonlyArray1<'_, f64>>() {
        // The fast path: a float64 vector, as every environment returns.
        a.as_array().to_vec()
    } else {
        let py = obj.py();
        let kwargs = PyDict::new(py);
        kwargs.set_item("dtype", "float64")?;
        let array = py
            .import("numpy")?
            .call_method("ascontiguousarray", (obj,), Some(&kwargs))
            .map_err(|_| PyTypeError::new_err(format!("expected {what} as numbers, got {}", type_name(obj))))?;
        let shape: Vec<usize> = array.getattr("shape")?.extract()?;
        if shape.len() != 1 {
            return Err(value_error(format!("expected {what} as a 1-D array of {dim} values, got shape {shape:?}")));
        }
        array.extract::<PyReadonlyArray1<'_, f64>>()?.as_array().to_vec()
    };
    if values.len() != dim {
        return Err(value_error(format!("expected {what} of {dim} values, got {}", values.len())));
    }
    if let Some(i) = values.iter().position(|v| !v.is_finite()) {
        return Err(value_error(format!("{what}: value {i} is {} (values must be finite)", values[i])));
    }
    Ok(values)
}

fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "an object".into())
}

/// One environment instance (see `domain.rs`); `rlfd`'s Gymnasium classes wrap it.
#[pyclass(module = "rlfd._rlfd")]
pub struct Env {
    domain: Domain,
    name: String,
}

fn keepaway_info<'py>(py: Python<'py>, domain: &Domain, end: bool) -> PyResult<Bound<'py, PyDict>> {
    let info = PyDict::new(py);
    if let Some(k) = domain.keepaway() {
        info.set_item("cycle", k.game.cycle())?;
        if end {
            info.set_item("final_smdp_rewards", PyArray1::from_vec(py, k.final_smdp_rewards()))?;
            let cause = match k.game.ended() {
                Some(rlfd_keepaway::EndCause::Out) => "out",
                Some(rlfd_keepaway::EndCause::Taken) => "taken",
                None => "running",
            };
            info.set_item("end_cause", cause)?;
        } else {
            info.set_item("keeper", k.keeper())?;
            info.set_item("smdp_reward", k.smdp_reward())?;
        }
    }
    Ok(info)
}

#[pymethods]
impl Env {
    /// `Env(domain, options)`: `domain` is "maze", "mario" or "keepaway".
    #[new]
    #[pyo3(signature = (domain, options=None))]
    fn new(domain: &str, options: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        guarded("Env()", || {
            let spec = spec_of(domain, options)?;
            Ok(Env { domain: Domain::new(spec).map_err(value_error)?, name: domain.to_string() })
        })
    }

    /// The domain's name.
    #[getter]
    fn domain(&self) -> &str {
        &self.name
    }

    #[getter]
    fn num_actions(&self) -> usize {
        self.domain.spec().num_actions()
    }

    #[getter]
    fn state_dim(&self) -> usize {
        self.domain.spec().state_dim()
    }

    #[getter]
    fn max_episode_steps(&self) -> Option<u64> {
        self.domain.spec().max_episode_steps()
    }

    #[getter]
    fn state_names(&self) -> Vec<String> {
        self.domain.spec().state_names()
    }

    #[getter]
    fn action_names(&self) -> Vec<String> {
        self.domain.spec().action_names()
    }

    /// (low, high) of the observation.
    fn bounds<'py>(&self, py: Python<'py>) -> (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>) {
        let (low, high) = self.domain.spec().bounds();
        (PyArray1::from_vec(py, low), PyArray1::from_vec(py, high))
    }

    /// Keepaway's configuration: (keepers, takers, region side in m).
    #[getter]
    fn keepaway_configuration(&self) -> Option<(usize, usize, f64)> {
        match self.domain.spec() {
            DomainSpec::Keepaway { keepers, takers, side, .. } => Some((*keepers, *takers, *side)),
            _ => None,
        }
    }

    /// Starts an episode (reseeding when `seed` is given); returns (observation, info).
    #[pyo3(signature = (seed=None))]
    fn reset<'py>(
        &mut self,
        py: Python<'py>,
        seed: Option<u64>,
    ) -> PyResult<(Bound<'py, PyArray1<f64>>, Bound<'py, PyDict>)> {
        guarded("reset()", || {
            self.domain.reset(seed);
            let info = keepaway_info(py, &self.domain, false)?;
            if let Some(k) = self.domain.keepaway() {
                info.set_item("skipped_episodes", k.skipped_episodes)?;
            }
            Ok((PyArray1::from_slice(py, self.domain.state()), info))
        })
    }

    /// One step: (observation, reward, terminated, truncated, info).
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        action: i64,
    ) -> PyResult<(Bound<'py, PyArray1<f64>>, f64, bool, bool, Bound<'py, PyDict>)> {
        guarded("step()", || {
            let a = self.domain.check_step(action).map_err(value_error)?;
            let o = self.domain.step(a);
            let info = keepaway_info(py, &self.domain, o.terminated || o.truncated)?;
            Ok((PyArray1::from_slice(py, self.domain.state()), o.reward, o.terminated, o.truncated, info))
        })
    }

    /// The current observation.
    fn state<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.domain.state())
    }

    /// Agent steps taken this episode.
    #[getter]
    fn steps(&self) -> u64 {
        self.domain.steps()
    }

    /// An RGB picture of the current state (height × width × 3, uint8).
    fn render<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<u8>>> {
        guarded("render()", || {
            if !self.domain.started() {
                return Err(value_error("call reset() before render()"));
            }
            let p = render(&self.domain);
            PyArray1::from_vec(py, p.pixels).reshape([p.height, p.width, 3])
        })
    }

    /// Keepaway: the benchmark policy's action now ("always-hold", "random",
    /// "hand-coded"); Random draws from this environment's generator, as the
    /// benchmark runs do.
    fn benchmark_action(&mut self, policy: &str) -> PyResult<usize> {
        guarded("benchmark_action()", || {
            let policy = benchmark_policy(policy)?;
            if !self.domain.started() || self.domain.done() {
                return Err(value_error("benchmark_action() needs a keeper deciding: call reset() first"));
            }
            self.domain.benchmark_action(policy).ok_or_else(|| value_error("benchmark policies are Keepaway's"))
        })
    }
}

fn benchmark_policy(name: &str) -> PyResult<BenchmarkPolicy> {
    BenchmarkPolicy::ALL.into_iter().find(|p| p.slug() == name).ok_or_else(|| {
        value_error(format!(
            "unknown benchmark policy {name:?}: expected one of {}",
            BenchmarkPolicy::ALL.map(BenchmarkPolicy::slug).join(", ")
        ))
    })
}

/// N instances of one environment stepped in Rust (see `vector.rs`).
#[pyclass(module = "rlfd._rlfd")]
pub struct VectorEnv {
    inner: VectorDomain,
}

type BatchOut<'py> = (
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<bool>>,
    Bound<'py, PyArray1<bool>>,
    Option<(Bound<'py, PyArray2<f64>>, Bound<'py, PyArray1<bool>>)>,
);

#[pymethods]
impl VectorEnv {
    #[new]
    #[pyo3(signature = (domain, num_envs, options=None))]
    fn new(domain: &str, num_envs: usize, options: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        guarded("VectorEnv()", || {
            let spec = spec_of(domain, options)?;
            Ok(VectorEnv { inner: VectorDomain::new(spec, num_envs).map_err(value_error)? })
        })
    }

    #[getter]
    fn num_envs(&self) -> usize {
        self.inner.len()
    }

    /// Resets every instance; returns the observations (num_envs × dim).
    #[pyo3(signature = (seed=None))]
    fn reset<'py>(&mut self, py: Python<'py>, seed: Option<u64>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        guarded("reset()", || {
            self.inner.reset(seed);
            observations(py, &self.inner.batch.observations, self.inner.dim())
        })
    }

    /// One step of every instance: (observations, rewards, terminated,
    /// truncated, (final observations, which) or None).
    fn step<'py>(&mut self, py: Python<'py>, actions: PyReadonlyArray1<'py, i64>) -> PyResult<BatchOut<'py>> {
        guarded("step()", || {
            let actions = actions.as_array();
            let actions: Vec<i64> = actions.iter().copied().collect();
            self.inner.step(&actions).map_err(value_error)?;
            let b = &self.inner.batch;
            let d = self.inner.dim();
            let finals = if b.has_final.iter().any(|&f| f) {
                Some((observations(py, &b.final_observations, d)?, PyArray1::from_slice(py, &b.has_final)))
            } else {
                None
            };
            Ok((
                observations(py, &b.observations, d)?,
                PyArray1::from_slice(py, &b.rewards),
                PyArray1::from_slice(py, &b.terminated),
                PyArray1::from_slice(py, &b.truncated),
                finals,
            ))
        })
    }

    /// Keepaway: each instance's deciding keeper now.
    fn keepers<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i64>> {
        let k: Vec<i64> = self.inner.envs().iter().map(|e| e.keepaway().map_or(-1, |k| k.keeper() as i64)).collect();
        PyArray1::from_vec(py, k)
    }
}

fn observations<'py>(py: Python<'py>, flat: &[f64], dim: usize) -> PyResult<Bound<'py, PyArray2<f64>>> {
    Array2::from_shape_vec((flat.len() / dim, dim), flat.to_vec())
        .map(|a| a.into_pyarray(py))
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

/// A Keepaway benchmark keeper policy as a callable on observations.
#[pyclass(module = "rlfd._rlfd")]
pub struct KeepawayPolicy {
    policy: BenchmarkPolicy,
    keepers: usize,
    takers: usize,
    rng: SimRng,
}

#[pymethods]
impl KeepawayPolicy {
    /// `KeepawayPolicy(name, keepers=3, takers=2, seed=0)`: Random draws from
    /// its own ChaCha8 generator seeded with `seed`.
    #[new]
    #[pyo3(signature = (name, keepers=3, takers=2, seed=0))]
    fn new(name: &str, keepers: usize, takers: usize, seed: u64) -> PyResult<Self> {
        let policy = benchmark_policy(name)?;
        if !(3..=5).contains(&keepers) || !(2..=4).contains(&takers) {
            return Err(value_error(format!("keepers must be 3 to 5 and takers 2 to 4, got {keepers} and {takers}")));
        }
        Ok(KeepawayPolicy { policy, keepers, takers, rng: seeded(seed) })
    }

    #[getter]
    fn name(&self) -> &'static str {
        self.policy.slug()
    }

    /// The action (0 Hold, i a pass to the i-th nearest teammate) in `observation`.
    fn __call__(&mut self, observation: &Bound<'_, PyAny>) -> PyResult<usize> {
        let n = rlfd_keepaway::state_len(self.keepers, self.takers);
        let what = format!("an observation of {} vs {}", self.keepers, self.takers);
        let state = state_arg(observation, n, &what)?;
        guarded("KeepawayPolicy()", || {
            Ok(self.policy.choose_in(&state, self.keepers, self.takers, &mut self.rng).index())
        })
    }
}

// ---------------------------------------------------------------- RIPPER

/// A fitted RIPPER decision list.
#[pyclass(module = "rlfd._rlfd", name = "DecisionList")]
pub struct PyDecisionList {
    list: DecisionList,
}

fn rows_of(x: &PyReadonlyArray2<'_, f64>) -> Vec<Vec<f64>> {
    x.as_array().rows().into_iter().map(|r| r.to_vec()).collect()
}

fn ripper_params(
    folds: usize,
    min_no: f64,
    optimizations: usize,
    seed: u64,
    check_error_rate: bool,
    prune: bool,
    random: &str,
) -> PyResult<RipperParams> {
    let random = match random {
        "weka" => RipperRandom::Weka,
        "chacha8" => RipperRandom::ChaCha8,
        other => return Err(value_error(format!("unknown random stream {other:?}: expected \"weka\" or \"chacha8\""))),
    };
    let params = RipperParams {
        folds,
        min_no,
        optimizations,
        seed,
        error_rate_check: if check_error_rate { ErrorRateCheck::StopAtHalf } else { ErrorRateCheck::Ignore },
        pruning: if prune { Pruning::Irep } else { Pruning::Off },
        random,
    };
    params.check().map_err(|e| value_error(e.to_string()))?;
    Ok(params)
}

#[allow(clippy::too_many_arguments)]
fn dataset(
    x: &PyReadonlyArray2<'_, f64>,
    y: &PyReadonlyArray1<'_, i64>,
    attribute_names: Vec<String>,
    nominal: Vec<Option<Vec<String>>>,
    class_attribute: String,
    class_names: Vec<String>,
    weights: Option<PyReadonlyArray1<'_, f64>>,
) -> PyResult<Dataset> {
    let rows = rows_of(x);
    let labels = y
        .as_array()
        .iter()
        .enumerate()
        .map(|(i, &l)| usize::try_from(l).map_err(|_| value_error(format!("row {i}: class label {l} is negative"))))
        .collect::<PyResult<Vec<usize>>>()?;
    if nominal.len() != attribute_names.len() {
        return Err(value_error("one nominal entry per attribute"));
    }
    let attributes = attribute_names
        .into_iter()
        .zip(nominal)
        .map(|(name, values)| match values {
            Some(values) => Attribute::nominal(name, values),
            None => Attribute::numeric(name),
        })
        .collect();
    let data =
        Dataset::new(attributes, rows, class_attribute, class_names, labels).map_err(|e| value_error(e.to_string()))?;
    match weights {
        Some(w) => data.with_weights(w.as_array().to_vec()).map_err(|e| value_error(e.to_string())),
        None => Ok(data),
    }
}

/// Fits RIPPER (Weka's JRip) on `x` (rows × attributes) and `y` (class indices).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (x, y, attribute_names, nominal, class_attribute, class_names, weights, folds, min_no, optimizations, seed, check_error_rate, prune, random))]
pub fn ripper_fit(
    x: PyReadonlyArray2<'_, f64>,
    y: PyReadonlyArray1<'_, i64>,
    attribute_names: Vec<String>,
    nominal: Vec<Option<Vec<String>>>,
    class_attribute: String,
    class_names: Vec<String>,
    weights: Option<PyReadonlyArray1<'_, f64>>,
    folds: usize,
    min_no: f64,
    optimizations: usize,
    seed: u64,
    check_error_rate: bool,
    prune: bool,
    random: &str,
) -> PyResult<PyDecisionList> {
    guarded("ripper fit", || {
        let params = ripper_params(folds, min_no, optimizations, seed, check_error_rate, prune, random)?;
        let data = dataset(&x, &y, attribute_names, nominal, class_attribute, class_names, weights)?;
        let list = Ripper::fit(&params, &data).map_err(|e| value_error(e.to_string()))?;
        Ok(PyDecisionList { list })
    })
}

/// Weka's stratified cross-validation of RIPPER: a dict with `accuracy`,
/// `correct`, `total` and `per_fold` (correct, total, rules).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (x, y, attribute_names, nominal, class_attribute, class_names, weights, folds, min_no, optimizations, seed, check_error_rate, prune, random, cv_folds, cv_seed))]
pub fn ripper_cross_validate<'py>(
    py: Python<'py>,
    x: PyReadonlyArray2<'_, f64>,
    y: PyReadonlyArray1<'_, i64>,
    attribute_names: Vec<String>,
    nominal: Vec<Option<Vec<String>>>,
    class_attribute: String,
    class_names: Vec<String>,
    weights: Option<PyReadonlyArray1<'_, f64>>,
    folds: usize,
    min_no: f64,
    optimizations: usize,
    seed: u64,
    check_error_rate: bool,
    prune: bool,
    random: &str,
    cv_folds: usize,
    cv_seed: u64,
) -> PyResult<Bound<'py, PyDict>> {
    guarded("ripper cross-validation", || {
        let params = ripper_params(folds, min_no, optimizations, seed, check_error_rate, prune, random)?;
        let data = dataset(&x, &y, attribute_names, nominal, class_attribute, class_names, weights)?;
        let cv =
            stratified_cross_validation(&params, &data, cv_folds, cv_seed).map_err(|e| value_error(e.to_string()))?;
        let out = PyDict::new(py);
        out.set_item("accuracy", cv.accuracy)?;
        out.set_item("correct", cv.correct)?;
        out.set_item("total", cv.total)?;
        let folds: Vec<(f64, f64, usize)> = cv.per_fold.iter().map(|f| (f.correct, f.total, f.rules)).collect();
        out.set_item("per_fold", folds)?;
        Ok(out)
    })
}

impl PyDecisionList {
    fn predict_with(&self, x: &Bound<'_, PyAny>, by_distribution: bool) -> PyResult<Vec<i64>> {
        let predict = |row: &[f64]| {
            (if by_distribution { self.list.predict_by_distribution(row) } else { self.list.predict(row) }) as i64
        };
        let width = self.list.attributes().len();
        let check = |n: usize| {
            if n == width {
                Ok(())
            } else {
                Err(value_error(format!("expected rows of {width} attribute values, got {n}")))
            }
        };
        if let Ok(x) = x.extract::<PyReadonlyArray2<'_, f64>>() {
            check(x.as_array().ncols())?;
            Ok(x.as_array().rows().into_iter().map(|r| predict(&r.to_vec())).collect())
        } else if let Ok(x) = x.extract::<PyReadonlyArray1<'_, f64>>() {
            let row = x.as_array().to_vec();
            check(row.len())?;
            Ok(vec![predict(&row)])
        } else {
            Err(PyTypeError::new_err("expected a float64 array of one row or of rows × attributes"))
        }
    }
}

#[pymethods]
impl PyDecisionList {
    /// The class of the first rule that covers each row (else the default class).
    fn predict<'py>(&self, py: Python<'py>, x: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArray1<i64>>> {
        guarded("predict()", || Ok(PyArray1::from_vec(py, self.predict_with(x, false)?)))
    }

    /// Weka's `classifyInstance`: the majority training class of the covering rule.
    fn predict_by_distribution<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        guarded("predict_by_distribution()", || Ok(PyArray1::from_vec(py, self.predict_with(x, true)?)))
    }

    /// The thesis's `if … elseif … else` listing, numbers with `precision` decimals.
    #[pyo3(signature = (precision=2))]
    fn to_string(&self, precision: usize) -> String {
        format!("{:.*}", precision, self.list)
    }

    fn __str__(&self) -> String {
        self.list.to_string()
    }

    fn __repr__(&self) -> String {
        format!("<DecisionList of {} rules and a default>", self.list.rules.len())
    }

    /// Weka's `JRip.toString()` listing.
    fn weka_string(&self) -> String {
        self.list.to_weka_string()
    }

    #[getter]
    fn default_class(&self) -> usize {
        self.list.default_class
    }

    #[getter]
    fn class_names(&self) -> Vec<String> {
        self.list.class_names().to_vec()
    }

    #[getter]
    fn attribute_names(&self) -> Vec<String> {
        self.list.attributes().iter().map(|a| a.name.clone()).collect()
    }

    /// The rules, in order: dicts of `conditions` ((attribute, op, value)
    /// with op "<=", ">=" or "=", the value a nominal attribute's name),
    /// `class`, `covered`, `false_positives`, `class_weights`.
    fn rules<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let out = PyList::empty(py);
        for rule in &self.list.rules {
            let d = PyDict::new(py);
            let mut conditions = Vec::new();
            for c in &rule.conditions {
                let attribute = &self.list.attributes()[c.attribute];
                let (op, value): (&str, Py<PyAny>) = match (c.op, &attribute.kind) {
                    (Operator::LessEq, _) => ("<=", c.value.into_pyobject(py)?.into_any().unbind()),
                    (Operator::GreaterEq, _) => (">=", c.value.into_pyobject(py)?.into_any().unbind()),
                    (Operator::Equal, AttributeKind::Nominal { values }) => {
                        let v = values.get(c.value as usize).cloned().unwrap_or_default();
                        ("=", v.into_pyobject(py)?.into_any().unbind())
                    }
                    (Operator::Equal, AttributeKind::Numeric) => ("=", c.value.into_pyobject(py)?.into_any().unbind()),
                };
                conditions.push((attribute.name.clone(), op, value));
            }
            d.set_item("conditions", conditions)?;
            d.set_item("class", rule.class)?;
            d.set_item("covered", rule.coverage.covered)?;
            d.set_item("false_positives", rule.coverage.false_positives)?;
            d.set_item("class_weights", rule.coverage.class_weights.clone())?;
            out.append(d)?;
        }
        Ok(out)
    }
}

// ---------------------------------------------------------------- RE-IRL

fn trajectories_of(list: &[PyReadonlyArray2<'_, f64>], which: &'static str) -> PyResult<Vec<Vec<Vec<f64>>>> {
    if list.is_empty() {
        return Err(value_error(IrlError::Empty(which).to_string()));
    }
    let first = list[0].as_array().nrows();
    let mut out = Vec::with_capacity(list.len());
    for (index, t) in list.iter().enumerate() {
        let a = t.as_array();
        if a.nrows() != first {
            return Err(value_error(
                IrlError::UnequalLengths { which, index, found: a.nrows(), expected: first }.to_string(),
            ));
        }
        out.push(a.rows().into_iter().map(|r| r.to_vec()).collect());
    }
    Ok(out)
}

/// RE-IRL (`rlfd_lfd::irl`) with the state variables as features: expert
/// and baseline trajectories (each observations × variables, all of one
/// length) in; a dict of the weights and the fit's diagnostics out.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (expert, baseline, discount, delta, epsilon, feature_ranges, scale_features, norm_bound, normalise, stopping_tolerance, max_iterations))]
pub fn relative_entropy<'py>(
    py: Python<'py>,
    expert: Vec<PyReadonlyArray2<'py, f64>>,
    baseline: Vec<PyReadonlyArray2<'py, f64>>,
    discount: f64,
    delta: Option<f64>,
    epsilon: Option<Vec<f64>>,
    feature_ranges: Vec<f64>,
    scale_features: bool,
    norm_bound: Option<f64>,
    normalise: bool,
    stopping_tolerance: f64,
    max_iterations: usize,
) -> PyResult<Bound<'py, PyDict>> {
    guarded("relative_entropy()", || {
        let expert = trajectories_of(&expert, "expert")?;
        let baseline = trajectories_of(&baseline, "baseline")?;
        let horizon = expert[0].len();
        if baseline[0].len() != horizon {
            return Err(value_error(format!(
                "baseline trajectories have {} observations, but the expert's have {horizon} (RE-IRL compares trajectories of one length)",
                baseline[0].len()
            )));
        }
        let dim = expert[0].first().map_or(0, Vec::len);
        for (which, set) in [("expert", &expert), ("baseline", &baseline)] {
            for (index, t) in set.iter().enumerate() {
                if let Some(row) = t.iter().find(|r| r.len() != dim) {
                    return Err(value_error(
                        IrlError::Dimension { which, index, found: row.len(), expected: dim }.to_string(),
                    ));
                }
            }
        }
        if feature_ranges.len() != dim {
            return Err(value_error(format!(
                "expected {dim} feature ranges (one per state variable), got {}",
                feature_ranges.len()
            )));
        }
        let tolerance = match (delta, epsilon) {
            (Some(_), Some(_)) => {
                return Err(value_error("give either delta (Hoeffding's tolerance) or epsilon, not both"));
            }
            (Some(delta), None) => Tolerance::Hoeffding { delta, feature_ranges: feature_ranges.clone() },
            (None, Some(e)) if e.len() == dim => Tolerance::PerFeature(e),
            (None, Some(e)) => return Err(value_error(format!("expected {dim} tolerances, got {}", e.len()))),
            (None, None) => Tolerance::Zero,
        };
        let params = RelativeEntropyIrlParams {
            discount,
            tolerance,
            feature_scale: if scale_features { IrlFeatureScale::Ranges(feature_ranges) } else { IrlFeatureScale::None },
            norm_bound,
            stopping: Stopping { tolerance: stopping_tolerance, max_iterations },
            normalisation: if normalise { Normalisation::UnitL2 } else { Normalisation::None },
        };
        let irl = RelativeEntropyIrl::new(params).map_err(|e| value_error(e.to_string()))?;
        let features = StateVariables { dim };
        let counts = |set: &Vec<Vec<Vec<f64>>>| -> Vec<Vec<f64>> {
            set.iter().map(|t| feature_counts(t.iter().map(Vec::as_slice), &features, discount)).collect()
        };
        let (expert_counts, baseline_counts) = (counts(&expert), counts(&baseline));
        let fit = irl.fit(&expert_counts, &baseline_counts, horizon).map_err(|e| value_error(e.to_string()))?;
        let out = PyDict::new(py);
        out.set_item("weights", PyArray1::from_vec(py, fit.weights))?;
        out.set_item("scaled_weights", PyArray1::from_vec(py, fit.scaled_weights))?;
        out.set_item("fitted_norm", fit.fitted_norm)?;
        out.set_item("expert_feature_counts", PyArray1::from_vec(py, fit.expert_feature_counts))?;
        out.set_item("tolerance", PyArray1::from_vec(py, fit.tolerance))?;
        out.set_item("objective", PyArray1::from_vec(py, fit.objective))?;
        out.set_item("converged", fit.converged)?;
        out.set_item("on_bound", fit.on_bound)?;
        out.set_item("residual", fit.residual)?;
        out.set_item("stability", fit.stability)?;
        out.set_item("iterations", fit.iterations)?;
        out.set_item("horizon", horizon)?;
        Ok(out)
    })
}

/// `n` rollouts of the uniformly random policy, each `horizon` observations
/// (an episode that ends early repeats its last observation), drawn as
/// `rlfd_lfd::irl::rollout_uniform` draws them: (n × horizon × dim).
#[pyfunction]
#[pyo3(signature = (domain, n, horizon, seed, options=None))]
pub fn uniform_rollouts<'py>(
    py: Python<'py>,
    domain: &str,
    n: usize,
    horizon: usize,
    seed: u64,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyArray3<f64>>> {
    guarded("uniform_rollouts()", || {
        let mut spec = spec_of(domain, options)?;
        if n == 0 || horizon == 0 {
            return Err(value_error("n and horizon must be at least 1"));
        }
        // rollout_uniform ignores step caps: only the task's end stops a walk.
        match &mut spec {
            DomainSpec::Maze { max_episode_steps, .. }
            | DomainSpec::Mario { max_episode_steps }
            | DomainSpec::Keepaway { max_episode_steps, .. } => *max_episode_steps = None,
        }
        let mut env = Domain::new(spec).map_err(value_error)?;
        let dim = env.spec().state_dim();
        let mut out = Vec::with_capacity(n * horizon * dim);
        env.reseed(seed);
        for _ in 0..n {
            env.reset(None);
            let mut done = false;
            for _ in 0..horizon {
                out.extend_from_slice(env.state());
                if !done {
                    let a = env.uniform_action();
                    done = env.step(a).terminated;
                }
            }
        }
        PyArray1::from_vec(py, out).reshape([n, horizon, dim])
    })
}

/// A linear reward `R(s) = θᵀ s` (RE-IRL's output), evaluated as the Rust
/// agents evaluate it: the potential of SIS.
#[pyclass(module = "rlfd._rlfd")]
pub struct LinearStateReward {
    reward: LinearReward<StateVariables>,
}

#[pymethods]
impl LinearStateReward {
    #[new]
    fn new(weights: Vec<f64>) -> PyResult<Self> {
        if weights.is_empty() || weights.len() > 64 || weights.iter().any(|w| !w.is_finite()) {
            return Err(value_error(format!("expected 1 to 64 finite weights, got {:?}", weights)));
        }
        let dim = weights.len();
        Ok(LinearStateReward { reward: LinearReward::new(weights, StateVariables { dim }) })
    }

    #[getter]
    fn weights(&self) -> Vec<f64> {
        self.reward.weights().to_vec()
    }

    fn __call__(&self, state: &Bound<'_, PyAny>) -> PyResult<f64> {
        let s = state_arg(state, self.reward.weights().len(), "a state")?;
        guarded("LinearStateReward()", || Ok(self.reward.value(&s)))
    }
}

/// The SBS potential (`rlfd_lfd::similarity`) over demonstrated pairs.
#[pyclass(module = "rlfd._rlfd")]
pub struct SimilarityPotentialPy {
    potential: SimilarityPotential,
    dim: usize,
    num_actions: usize,
}

#[pymethods]
impl SimilarityPotentialPy {
    #[new]
    fn new(
        states: PyReadonlyArray2<'_, f64>,
        actions: PyReadonlyArray1<'_, i64>,
        num_actions: usize,
        sigma: Vec<f64>,
    ) -> PyResult<Self> {
        guarded("SimilarityPotential()", || {
            let rows = rows_of(&states);
            let acts: Vec<i64> = actions.as_array().to_vec();
            if rows.len() != acts.len() {
                return Err(value_error(format!("{} states but {} actions", rows.len(), acts.len())));
            }
            if num_actions == 0 {
                return Err(value_error("num_actions must be at least 1"));
            }
            if sigma.len() > 64 {
                return Err(value_error("at most 64 state variables"));
            }
            let acts = acts
                .iter()
                .enumerate()
                .map(|(i, &a)| {
                    usize::try_from(a)
                        .map_err(|_| value_error(format!("demonstrated pair {i}: action {a} is negative")))
                })
                .collect::<PyResult<Vec<usize>>>()?;
            let pairs = rows.iter().map(Vec::as_slice).zip(acts.iter().copied());
            let potential =
                SimilarityPotential::new(pairs, num_actions, &sigma).map_err(|e| value_error(e.to_string()))?;
            Ok(SimilarityPotentialPy { potential, dim: sigma.len(), num_actions })
        })
    }

    /// Φ(s, a) for every action a.
    fn __call__<'py>(&self, py: Python<'py>, state: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let s = state_arg(state, self.dim, "a state")?;
        guarded("SimilarityPotential()", || {
            let mut out = vec![0.0; self.num_actions];
            self.potential.values(&s, &mut out);
            Ok(PyArray1::from_vec(py, out))
        })
    }
}

/// A tile coder (`rlfd_rl::features::TileCoder`, dense indexing over a box).
#[pyclass(module = "rlfd._rlfd", name = "TileCoder")]
pub struct TileCoderPy {
    coder: TileCoder,
    buffer: ActiveFeatures,
    dim: usize,
}

#[pymethods]
impl TileCoderPy {
    #[new]
    fn new(tilings: usize, widths: Vec<f64>, lower: Vec<f64>, upper: Vec<f64>) -> PyResult<Self> {
        guarded("TileCoder()", || {
            let dim = widths.len();
            if lower.len() != dim || upper.len() != dim {
                return Err(value_error(format!("widths, lower and upper must have one entry per dimension ({dim})")));
            }
            let coder = TileCoder::new(tilings, &widths, TileIndexing::Dense { lower, upper })
                .map_err(|e| value_error(e.to_string()))?;
            let buffer = ActiveFeatures::with_capacity(coder.max_active());
            Ok(TileCoderPy { coder, buffer, dim })
        })
    }

    #[getter]
    fn num_features(&self) -> usize {
        self.coder.num_features()
    }

    /// The indices of the active tiles of `state` (one per tiling).
    fn __call__<'py>(&mut self, py: Python<'py>, state: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let s = state_arg(state, self.dim, "a state")?;
        guarded("TileCoder()", || {
            self.coder.features(&s, &mut self.buffer);
            Ok(PyArray1::from_vec(py, self.buffer.indices.iter().map(|&i| i64::from(i)).collect()))
        })
    }
}

/// DIS (`rlfd_rl::shaping::DynamicShaping`): a secondary SARSA learns `Φ†`
/// on `−R†(s)` over a tile coder's features, and each transition's shaping
/// reward is `scale · (γ Φ†(s', a') − Φ†_old(s, a))`.
#[pyclass(module = "rlfd._rlfd", name = "DynamicShaping")]
pub struct DynamicShapingPy {
    shaping: DynamicShaping<LinearReward<StateVariables>>,
    coder: TileCoder,
    from: ActiveFeatures,
    next: ActiveFeatures,
    dim: usize,
    num_actions: usize,
}

#[pymethods]
impl DynamicShapingPy {
    /// `DynamicShaping(coder, num_actions, weights, beta, scale)`: `R†(s) = weights · s`.
    #[new]
    fn new(coder: &TileCoderPy, num_actions: usize, weights: Vec<f64>, beta: f64, scale: f64) -> PyResult<Self> {
        let dim = coder.dim;
        if weights.len() != dim || weights.iter().any(|w| !w.is_finite()) {
            return Err(value_error(format!(
                "expected {dim} finite weights (one per state variable), got {weights:?}"
            )));
        }
        if num_actions == 0 || !(beta.is_finite() && beta > 0.0) || !scale.is_finite() {
            return Err(value_error(format!(
                "num_actions must be at least 1, beta finite and > 0, scale finite; got {num_actions}, {beta}, {scale}"
            )));
        }
        let reward = LinearReward::new(weights, StateVariables { dim });
        let shaping =
            DynamicShaping::new(coder.coder.num_features(), num_actions, reward, beta, scale, Selection::Uncorrected);
        let capacity = coder.coder.max_active();
        Ok(DynamicShapingPy {
            shaping,
            coder: coder.coder.clone(),
            from: ActiveFeatures::with_capacity(capacity),
            next: ActiveFeatures::with_capacity(capacity),
            dim,
            num_actions,
        })
    }

    /// `scale · Φ†(s, ·)`, one value per action.
    fn potentials<'py>(&mut self, py: Python<'py>, state: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let s = state_arg(state, self.dim, "a state")?;
        guarded("DynamicShaping.potentials()", || {
            self.coder.features(&s, &mut self.from);
            let mut out = vec![0.0; self.num_actions];
            let visit = Visit { state: &s, features: &self.from };
            self.shaping.potentials(&visit, &mut out);
            Ok(PyArray1::from_vec(py, out))
        })
    }

    /// Learns from the transition `(s, a) → (s', a')` and returns its shaping
    /// reward; `next_state=None` when `s'` is terminal.
    #[pyo3(signature = (state, action, next_state, next_action, gamma=1.0))]
    fn reward(
        &mut self,
        state: &Bound<'_, PyAny>,
        action: usize,
        next_state: Option<&Bound<'_, PyAny>>,
        next_action: Option<usize>,
        gamma: f64,
    ) -> PyResult<f64> {
        let s = state_arg(state, self.dim, "a state")?;
        let n = self.num_actions;
        let check = |a: usize, what: &str| {
            if a < n { Ok(a) } else { Err(value_error(format!("{what} {a} is out of range: expected 0 to {}", n - 1))) }
        };
        check(action, "action")?;
        if !(0.0..=1.0).contains(&gamma) {
            return Err(value_error(format!("gamma must be in [0, 1], got {gamma}")));
        }
        let next = match (next_state, next_action) {
            (Some(ns), Some(na)) => Some((state_arg(ns, self.dim, "the next state")?, check(na, "next action")?)),
            (None, None) => None,
            _ => return Err(value_error("give next_state and next_action together (both None at a terminal state)")),
        };
        guarded("DynamicShaping.reward()", || {
            self.coder.features(&s, &mut self.from);
            let zeros = vec![0.0; n];
            if let Some((ns, _)) = &next {
                self.coder.features(ns, &mut self.next);
            }
            let t = Transition {
                from: Visit { state: &s, features: &self.from },
                action,
                potentials: &zeros,
                next: next.as_ref().map(|(ns, na)| Next {
                    visit: Visit { state: ns, features: &self.next },
                    action: *na,
                    target: *na,
                    potentials: &zeros,
                }),
                terminal_state: None,
                gamma,
            };
            Ok(self.shaping.reward(&t))
        })
    }
}

// ---------------------------------------------------------------- demonstrations

/// A checked set of demonstrations (`rlfd_env::demonstration::DemonstrationSet`).
#[pyclass(module = "rlfd._rlfd", name = "DemonstrationSet")]
pub struct PyDemonstrationSet {
    set: DemonstrationSet,
}

fn set_error(e: impl ToString) -> PyErr {
    value_error(e.to_string())
}

#[pymethods]
impl PyDemonstrationSet {
    /// Builds a set from (states, actions or None) pairs.
    #[new]
    #[pyo3(signature = (trajectories, state_names=None, num_actions=None))]
    fn new(
        trajectories: Vec<(PyReadonlyArray2<'_, f64>, Option<PyReadonlyArray1<'_, i64>>)>,
        state_names: Option<Vec<String>>,
        num_actions: Option<usize>,
    ) -> PyResult<Self> {
        guarded("DemonstrationSet()", || {
            let mut list = Vec::with_capacity(trajectories.len());
            for (index, (states, actions)) in trajectories.iter().enumerate() {
                let a = states.as_array();
                let values: Vec<f64> = a.rows().into_iter().flat_map(|r| r.to_vec()).collect();
                let actions = match actions {
                    Some(acts) => Some(
                        acts.as_array()
                            .iter()
                            .enumerate()
                            .map(|(step, &x)| {
                                usize::try_from(x).map_err(|_| {
                                    value_error(format!("trajectory {index}: step {step}: action {x} is negative"))
                                })
                            })
                            .collect::<PyResult<Vec<usize>>>()?,
                    ),
                    None => None,
                };
                let t = Trajectory::new(values, a.ncols(), actions)
                    .map_err(|e| value_error(format!("trajectory {index}: {e}")))?;
                list.push(t);
            }
            let dim = list.first().map_or(0, Trajectory::dimension);
            let names = state_names.unwrap_or_else(|| rlfd_env::demonstration::default_state_names(dim.max(1)));
            let set = DemonstrationSet::new(names, num_actions, list).map_err(set_error)?;
            Ok(PyDemonstrationSet { set })
        })
    }

    /// Reads a `.csv` or `.jsonl` file (errors name the file, line and field).
    #[staticmethod]
    #[pyo3(signature = (path, num_actions=None))]
    fn read(path: std::path::PathBuf, num_actions: Option<usize>) -> PyResult<Self> {
        guarded("read()", || {
            Ok(PyDemonstrationSet { set: DemonstrationSet::read_path(&path, num_actions).map_err(set_error)? })
        })
    }

    /// Reads text in `format` ("csv" or "jsonl"); `name` is used in errors.
    #[staticmethod]
    #[pyo3(signature = (text, format, name="<string>", num_actions=None))]
    fn parse(text: &str, format: &str, name: &str, num_actions: Option<usize>) -> PyResult<Self> {
        guarded("parse()", || {
            let format = format_of(format)?;
            let set = DemonstrationSet::read(text.as_bytes(), name, format, num_actions).map_err(set_error)?;
            Ok(PyDemonstrationSet { set })
        })
    }

    /// The set as text in `format` ("csv" or "jsonl").
    fn dumps(&self, format: &str) -> PyResult<String> {
        let mut out = Vec::new();
        self.set.write(&mut out, format_of(format)?).map_err(set_error)?;
        String::from_utf8(out).map_err(set_error)
    }

    /// Writes the set, in the format the path's extension names.
    fn write(&self, path: std::path::PathBuf) -> PyResult<()> {
        let format = Format::from_path(&path).ok_or_else(|| {
            value_error(format!("{}: unknown file format (expected a .csv or .jsonl file)", path.display()))
        })?;
        let file =
            std::fs::File::create(&path).map_err(|e| value_error(format!("{}: cannot write: {e}", path.display())))?;
        let mut w = std::io::BufWriter::new(file);
        self.set.write(&mut w, format).map_err(|e| value_error(format!("{}: cannot write: {e}", path.display())))?;
        std::io::Write::flush(&mut w).map_err(|e| value_error(format!("{}: cannot write: {e}", path.display())))
    }

    #[getter]
    fn state_names(&self) -> Vec<String> {
        self.set.state_names().to_vec()
    }

    #[getter]
    fn num_actions(&self) -> Option<usize> {
        self.set.num_actions()
    }

    #[getter]
    fn has_actions(&self) -> bool {
        self.set.has_actions()
    }

    fn __len__(&self) -> usize {
        self.set.len()
    }

    /// Each trajectory's number of states.
    fn lengths(&self) -> Vec<usize> {
        self.set.lengths()
    }

    /// The trajectories as (states array, actions array or None).
    #[allow(clippy::type_complexity)]
    fn trajectories<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<Vec<(Bound<'py, PyArray2<f64>>, Option<Bound<'py, PyArray1<i64>>>)>> {
        self.set
            .trajectories()
            .iter()
            .map(|t| {
                let states = observations(py, t.values(), t.dimension())?;
                let actions = t.actions().map(|a| PyArray1::from_vec(py, a.iter().map(|&x| x as i64).collect()));
                Ok((states, actions))
            })
            .collect()
    }

    /// Every (state, action) pair with an action: (states, actions) arrays.
    fn state_action_pairs<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyArray2<f64>>, Bound<'py, PyArray1<i64>>)> {
        let mut states = Vec::new();
        let mut actions = Vec::new();
        for (s, a) in self.set.state_action_pairs() {
            states.extend_from_slice(s);
            actions.push(a as i64);
        }
        if actions.is_empty() {
            return Err(value_error("the set has no actions"));
        }
        Ok((observations(py, &states, self.set.dimension())?, PyArray1::from_vec(py, actions)))
    }

    /// Every trajectory padded to the longest by repeating its last state (the Maze's RE-IRL input).
    fn pad_to_equal_length(&self) -> Self {
        PyDemonstrationSet { set: self.set.pad_to_equal_length() }
    }

    /// Every trajectory cut to the k-th longest length, shorter ones dropped (Mario's RE-IRL input).
    fn prune_to_kth_longest(&self, k: usize) -> PyResult<Self> {
        Ok(PyDemonstrationSet { set: self.set.prune_to_kth_longest(k).map_err(set_error)? })
    }

    /// The first `n` observations of every trajectory (all must be that long).
    fn first_n_observations(&self, n: usize) -> PyResult<Self> {
        Ok(PyDemonstrationSet { set: self.set.first_n_observations(n).map_err(set_error)? })
    }
}

fn format_of(format: &str) -> PyResult<Format> {
    match format {
        "csv" => Ok(Format::Csv),
        "jsonl" => Ok(Format::JsonLines),
        other => Err(value_error(format!("unknown demonstration format {other:?}: expected \"csv\" or \"jsonl\""))),
    }
}

/// The `rlfd._rlfd` module.
#[pymodule]
pub fn _rlfd(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Env>()?;
    m.add_class::<VectorEnv>()?;
    m.add_class::<KeepawayPolicy>()?;
    m.add_class::<PyDecisionList>()?;
    m.add_class::<LinearStateReward>()?;
    m.add_class::<SimilarityPotentialPy>()?;
    m.add_class::<TileCoderPy>()?;
    m.add_class::<DynamicShapingPy>()?;
    m.add_class::<PyDemonstrationSet>()?;
    m.add_function(wrap_pyfunction!(ripper_fit, m)?)?;
    m.add_function(wrap_pyfunction!(ripper_cross_validate, m)?)?;
    m.add_function(wrap_pyfunction!(relative_entropy, m)?)?;
    m.add_function(wrap_pyfunction!(uniform_rollouts, m)?)?;
    m.add("DOMAINS", crate::domain::DOMAINS.to_vec())?;
    Ok(())
}
