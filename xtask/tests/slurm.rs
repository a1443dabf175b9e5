//! The cluster path on a real Slurm: a single-node cluster started on this
//! machine (Debian's `slurm-wlm` and `munge`), the scripts `cargo xtask
//! slurm` writes submitted to it, one array task cancelled midway and the
//! jobs submitted again, and the report compared byte for byte with a
//! single-process run's.
//!
//! It starts daemons as root, so it runs only when `RLFD_SLURM_TEST=1`
//! (`.ci/run` sets it after installing the packages); otherwise it says it
//! is skipped and passes. Everything it starts lives in a scratch directory
//! under the system's temporary directory: a fresh munge key, a `munged` on
//! its own socket, a generated `slurm.conf` (node `rlfdnode` on 127.0.0.1, 2
//! CPUs, free ports, no accounting, no cgroups), `slurmctld -D` and
//! `slurmd -D`, each a child process of the test. A guard stops them on
//! every exit path: jobs cancelled first, then each daemon by its process
//! id (SIGTERM, then SIGKILL after 10 s).
//!
//! The run: a quick-scale robustness run with 2 replication seeds (every
//! chapter, every reading), 4 array tasks of 1 CPU each (so 2 run at a
//! time). As soon as task 2 reports its first finished group it is
//! cancelled (`scancel JOB_2`); when the other tasks are done, the report
//! job (whose `afterok` dependency can no longer be met) is cancelled too.
//! The records on disk are noted (path, inode, modification time), and
//! `submit.sh` runs again. The second round must compute exactly the
//! trials that had no record, leave every noted record untouched, and end
//! with the report job writing a report identical, file for file and byte
//! for byte (but `run.json`), to the one `cargo xtask reproduce` writes in
//! one process.

use std::collections::BTreeMap;
use std::fs;
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

const FLAGS: [&str; 5] = ["--scale", "quick", "--robustness", "--seeds", "2"];

/// The daemons this test started, stopped when it ends.
struct Cluster {
    dir: PathBuf,
    conf: PathBuf,
    daemons: Vec<(&'static str, Child)>,
}

impl Cluster {
    fn start(dir: &Path) -> Cluster {
        let munge = dir.join("munge");
        fs::create_dir_all(&munge).unwrap();
        for sub in ["state", "spool", "log"] {
            fs::create_dir_all(dir.join(sub)).unwrap();
        }
        // munged wants its socket's directory reachable by all and its key private.
        set_mode(dir, 0o755);
        set_mode(&munge, 0o755);
        let mut key = vec![0u8; 1024];
        std::io::Read::read_exact(&mut fs::File::open("/dev/urandom").unwrap(), &mut key).unwrap();
        let key_file = munge.join("munge.key");
        fs::write(&key_file, &key).unwrap();
        set_mode(&key_file, 0o400);
        let socket = munge.join("munge.sock");
        let mut cluster = Cluster { dir: dir.to_path_buf(), conf: dir.join("slurm.conf"), daemons: Vec::new() };
        let munged = Command::new("munged")
            .arg("-F")
            .arg(format!("--key-file={}", key_file.display()))
            .arg(format!("--socket={}", socket.display()))
            .arg(format!("--pid-file={}", munge.join("munged.pid").display()))
            .arg(format!("--log-file={}", munge.join("munged.log").display()))
            .arg(format!("--seed-file={}", munge.join("munged.seed").display()))
            .stdout(Stdio::null())
            .stderr(log(dir, "munged.out"))
            .spawn()
            .expect("munged starts (apt-get install munge)");
        cluster.daemons.push(("munged", munged));
        wait_for("munged's socket", Duration::from_secs(30), || socket.exists());
        let (ctld_port, d_port) = (free_port(), free_port());
        let d = dir.display();
        let conf = format!(
            "ClusterName=rlfdtest\n\
             SlurmctldHost=localhost(127.0.0.1)\n\
             SlurmctldPort={ctld_port}\n\
             SlurmdPort={d_port}\n\
             SlurmUser=root\n\
             SlurmdUser=root\n\
             AuthType=auth/munge\n\
             CredType=cred/munge\n\
             AuthInfo=socket={}\n\
             StateSaveLocation={d}/state\n\
             SlurmdSpoolDir={d}/spool\n\
             SlurmctldPidFile={d}/slurmctld.pid\n\
             SlurmdPidFile={d}/slurmd.pid\n\
             SlurmctldLogFile={d}/log/slurmctld.log\n\
             SlurmdLogFile={d}/log/slurmd.log\n\
             PlugStackConfig={d}/plugstack.conf\n\
             ProctrackType=proctrack/linuxproc\n\
             TaskPlugin=task/none\n\
             JobAcctGatherType=jobacct_gather/none\n\
             AccountingStorageType=accounting_storage/none\n\
             JobCompType=jobcomp/none\n\
             SchedulerType=sched/backfill\n\
             SelectType=select/cons_tres\n\
             SelectTypeParameters=CR_CPU_Memory\n\
             MinJobAge=3600\n\
             ReturnToService=2\n\
             MpiDefault=none\n\
             SwitchType=switch/none\n\
             NodeName=rlfdnode NodeHostname={} NodeAddr=127.0.0.1 CPUs=2 RealMemory=8192 State=UNKNOWN\n\
             PartitionName=rlfd Nodes=rlfdnode Default=YES MaxTime=INFINITE State=UP\n",
            socket.display(),
            short_hostname(),
        );
        fs::write(&cluster.conf, conf).unwrap();
        fs::write(dir.join("plugstack.conf"), "").unwrap();
        let ctld = Command::new("slurmctld")
            .arg("-D")
            .arg("-f")
            .arg(&cluster.conf)
            .stdout(Stdio::null())
            .stderr(log(dir, "slurmctld.out"))
            .spawn()
            .expect("slurmctld starts (apt-get install slurm-wlm)");
        cluster.daemons.push(("slurmctld", ctld));
        let slurmd = Command::new("slurmd")
            .args(["-D", "-N", "rlfdnode", "-f"])
            .arg(&cluster.conf)
            .stdout(Stdio::null())
            .stderr(log(dir, "slurmd.out"))
            .spawn()
            .expect("slurmd starts");
        cluster.daemons.push(("slurmd", slurmd));
        wait_for("the node to be idle", Duration::from_secs(120), || {
            let out = cluster.command("sinfo").args(["-h", "-o", "%T"]).output().unwrap();
            String::from_utf8_lossy(&out.stdout).trim() == "idle"
        });
        cluster
    }

    /// A Slurm client command talking to this cluster.
    fn command(&self, program: &str) -> Command {
        let mut c = Command::new(program);
        c.env("SLURM_CONF", &self.conf);
        c
    }

    /// The ids of the jobs in the queue, with their state.
    fn queue(&self) -> Vec<(String, String)> {
        let out = self.command("squeue").args(["-h", "-r", "-o", "%i %T"]).output().unwrap();
        String::from_utf8_lossy(&out.stdout)
            .lines()
            .filter_map(|l| l.split_once(' ').map(|(a, b)| (a.to_string(), b.to_string())))
            .collect()
    }

    /// Waits until the queue holds no job but those `keep` accepts.
    fn wait_until_only(&self, what: &str, keep: impl Fn(&str, &str) -> bool) {
        wait_for(what, Duration::from_secs(1800), || self.queue().iter().all(|(id, state)| keep(id, state)));
    }

    /// A finished job's state (`COMPLETED`, `CANCELLED`, …).
    fn state(&self, job: &str) -> String {
        let out = self.command("scontrol").args(["show", "job", "-o", job]).output().unwrap();
        let text = String::from_utf8_lossy(&out.stdout).into_owned();
        text.split_whitespace()
            .find_map(|w| w.strip_prefix("JobState="))
            .map_or_else(|| format!("unknown ({text})"), str::to_string)
    }
}

impl Drop for Cluster {
    fn drop(&mut self) {
        let _ = self.command("scancel").args(["--user", "root"]).status();
        let deadline = Instant::now() + Duration::from_secs(30);
        while Instant::now() < deadline && !self.queue().is_empty() {
            std::thread::sleep(Duration::from_millis(500));
        }
        for (name, child) in self.daemons.iter_mut().rev() {
            let _ = Command::new("kill").arg("-TERM").arg(child.id().to_string()).status();
            let deadline = Instant::now() + Duration::from_secs(10);
            while Instant::now() < deadline && matches!(child.try_wait(), Ok(None)) {
                std::thread::sleep(Duration::from_millis(100));
            }
            if matches!(child.try_wait(), Ok(None)) {
                eprintln!("{name} did not stop on SIGTERM; killing it");
                let _ = child.kill();
            }
            let _ = child.wait();
        }
        eprintln!("stopped munged, slurmctld and slurmd (logs in {})", self.dir.display());
    }
}

fn set_mode(path: &Path, mode: u32) {
    use std::os::unix::fs::PermissionsExt;
    fs::set_permissions(path, fs::Permissions::from_mode(mode)).unwrap();
}

fn log(dir: &Path, name: &str) -> Stdio {
    Stdio::from(fs::File::create(dir.join("log").join(name)).unwrap())
}

fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port()
}

fn short_hostname() -> String {
    let out = Command::new("hostname").arg("-s").output().unwrap();
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

fn wait_for(what: &str, limit: Duration, mut done: impl FnMut() -> bool) {
    let start = Instant::now();
    while !done() {
        assert!(start.elapsed() < limit, "timed out after {limit:?} waiting for {what}");
        std::thread::sleep(Duration::from_millis(200));
    }
}

fn xtask() -> Command {
    Command::new(env!("CARGO_BIN_EXE_xtask"))
}

/// Every record in the store: path → (inode, modification time in ns).
fn records(store: &Path) -> BTreeMap<PathBuf, (u64, i64)> {
    fn walk(dir: &Path, out: &mut BTreeMap<PathBuf, (u64, i64)>) {
        let Ok(entries) = fs::read_dir(dir) else { return };
        for e in entries {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "json")
                && !p.file_name().unwrap().to_string_lossy().starts_with('.')
            {
                let m = fs::metadata(&p).unwrap();
                out.insert(p, (m.ino(), m.mtime() * 1_000_000_000 + m.mtime_nsec()));
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(store, &mut out);
    out
}

/// Every file under `dir` but run.json, with its bytes, sorted by path.
fn tree(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    fn walk(base: &Path, dir: &Path, out: &mut Vec<(PathBuf, Vec<u8>)>) {
        for e in fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(base, &p, out);
            } else if p.file_name().unwrap() != "run.json" {
                out.push((p.strip_prefix(base).unwrap().to_path_buf(), fs::read(&p).unwrap()));
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, dir, &mut out);
    out.sort();
    out
}

/// The sum of "N trials computed" over the shard logs of job `job`.
fn computed_in_logs(logs: &Path, job: &str) -> usize {
    let mut sum = 0;
    let mut finished = 0;
    for e in fs::read_dir(logs).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        if !name.starts_with(&format!("shard-{job}_")) {
            continue;
        }
        let text = fs::read_to_string(&p).unwrap();
        let last = text.lines().rfind(|l| l.contains("trials computed")).unwrap_or_else(|| panic!("{name}: {text}"));
        let n = last.split(": ").nth(1).and_then(|w| w.split_whitespace().next()).unwrap();
        sum += n.parse::<usize>().unwrap();
        finished += 1;
    }
    assert_eq!(finished, 4, "every task of job {job} finished");
    sum
}

/// The job id `submit.sh` printed for the shards.
fn submitted_shards(stderr_and_stdout: &str) -> String {
    let line = stderr_and_stdout
        .lines()
        .find(|l| l.starts_with("submitted: shards job "))
        .expect("submit.sh says what it submitted");
    line["submitted: shards job ".len()..].split_whitespace().next().unwrap().to_string()
}

#[test]
fn a_robustness_run_on_slurm_resumes_after_a_cancelled_task_and_reports_what_one_process_reports() {
    if std::env::var("RLFD_SLURM_TEST").as_deref() != Ok("1") {
        eprintln!(
            "skipped: the Slurm test starts munged, slurmctld and slurmd as root; set RLFD_SLURM_TEST=1 where Debian's slurm-wlm and munge are installed (.ci/run does)"
        );
        return;
    }
    let started = Instant::now();
    let dir = std::env::temp_dir().join(format!("rlfd-slurm-test-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    let cluster = Cluster::start(&dir.join("cluster"));
    eprintln!("cluster up after {:.1} s", started.elapsed().as_secs_f64());
    let (store, report, scripts) = (dir.join("results"), dir.join("report"), dir.join("slurm"));

    // Round 1: write and submit; cancel task 2 once it has stored a group.
    let out = xtask()
        .env("SLURM_CONF", &cluster.conf)
        .args(["slurm", "--shards", "4", "--cpus-per-task", "1", "--submit"])
        .args(FLAGS)
        .arg("--results")
        .arg(&store)
        .arg("--out")
        .arg(&report)
        .arg("--dir")
        .arg(&scripts)
        .output()
        .unwrap();
    let said = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{said}");
    let job = submitted_shards(&said);
    let plan_trials: usize = said
        .split("shards of ")
        .nth(1)
        .and_then(|t| t.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .expect("slurm says how many trials it planned");
    eprintln!("round 1: job {job}, {plan_trials} trials planned, after {:.1} s", started.elapsed().as_secs_f64());
    let task2_log = scripts.join("logs").join(format!("shard-{job}_2.out"));
    wait_for("task 2 to store its first group", Duration::from_secs(1800), || {
        fs::read_to_string(&task2_log).is_ok_and(|t| t.lines().any(|l| l.contains(" computed, ")))
    });
    let status = cluster.command("scancel").arg(format!("{job}_2")).status().unwrap();
    assert!(status.success());
    cluster.wait_until_only("the other tasks to finish", |id, state| {
        !id.starts_with(&format!("{job}_")) && state == "PENDING"
    });
    let _ = cluster.command("scancel").args(["--user", "root"]).status();
    cluster.wait_until_only("the queue to empty", |_, _| false);
    assert_eq!(cluster.state(&format!("{job}_2")), "CANCELLED", "task 2 was cancelled");
    let before = records(&store);
    eprintln!(
        "round 1 ended after {:.1} s: {} of {plan_trials} trials stored",
        started.elapsed().as_secs_f64(),
        before.len()
    );
    assert!(before.len() < plan_trials, "the cancelled task left trials to compute");
    assert!(!report.join("index.html").exists(), "no report before every shard succeeded");

    // Round 2: submit the same scripts again.
    let out = cluster.command("bash").arg(scripts.join("submit.sh")).output().unwrap();
    let said = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{said}");
    let job2 = submitted_shards(&said);
    cluster.wait_until_only("round 2 to finish", |_, _| false);
    for task in 1..=4 {
        assert_eq!(cluster.state(&format!("{job2}_{task}")), "COMPLETED", "round 2 task {task}");
    }
    let after = records(&store);
    assert_eq!(after.len(), plan_trials, "every planned trial has its record");
    for (path, stamp) in &before {
        assert_eq!(after.get(path), Some(stamp), "{} was rewritten", path.display());
    }
    let recomputed = computed_in_logs(&scripts.join("logs"), &job2);
    assert_eq!(recomputed, plan_trials - before.len(), "round 2 computed exactly the trials without a record");
    eprintln!("round 2 computed {recomputed} trials, after {:.1} s", started.elapsed().as_secs_f64());

    // The report job's report is the single-process run's, byte for byte.
    let single = dir.join("single");
    let out = xtask()
        .args(["reproduce", "--no-progress", "--jobs", "2"])
        .args(FLAGS)
        .arg("--results")
        .arg(single.join("results"))
        .arg("--out")
        .arg(single.join("report"))
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let (sharded, whole) = (tree(&report), tree(&single.join("report")));
    let names = |t: &[(PathBuf, Vec<u8>)]| t.iter().map(|(p, _)| p.clone()).collect::<Vec<_>>();
    assert_eq!(names(&sharded), names(&whole), "the file sets differ");
    for ((p, x), (_, y)) in sharded.iter().zip(&whole) {
        assert!(x == y, "{} differs between the Slurm run and the single process", p.display());
    }
    assert!(sharded.len() > 40, "a four-chapter report has many files");
    drop(cluster);
    eprintln!("the Slurm test took {:.1} s", started.elapsed().as_secs_f64());
    fs::remove_dir_all(&dir).unwrap();
}
