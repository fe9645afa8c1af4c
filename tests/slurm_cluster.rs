//! A contact ensemble as a SLURM job array on a real scheduler: a
//! single-node cluster on this machine (munged, slurmctld and slurmd, as
//! root, each with its own socket, ports and folders in a temporary
//! folder, so that nothing of another cluster is touched), the script
//! `export --slurm-array 4` prints submitted with `sbatch`, one of its
//! tasks cancelled midway, the script submitted again — only that task's
//! part is solved again — and the parts merged into exactly what one
//! machine's `--seeds 8` writes. A grid beyond the node's memory is refused
//! before anything is submitted. Every daemon the test starts is stopped
//! when it ends, on failure too.
//!
//! Skipped, saying why, when not run as root or without Debian's
//! `slurm-wlm` and `munge`, unless `ROUGHTUI_REQUIRE_SLURM=1` (CI sets
//! it, and `.ci/run` installs them).

mod common;

use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

use common::cli::BIN;

/// Why the cluster cannot be started here, if it cannot.
fn missing() -> Option<String> {
    let root = std::fs::metadata("/proc/self").is_ok_and(|m| m.uid() == 0);
    if !root {
        return Some("not run as root (slurmctld and slurmd run as root)".into());
    }
    for bin in [
        "munged",
        "slurmctld",
        "slurmd",
        "sbatch",
        "squeue",
        "scancel",
        "sinfo",
    ] {
        let found = std::env::var_os("PATH")
            .map(|p| std::env::split_paths(&p).any(|d| d.join(bin).is_file()))
            .unwrap_or(false)
            || Path::new("/usr/sbin").join(bin).is_file();
        if !found {
            return Some(format!("no {bin} (apt-get install slurm-wlm munge)"));
        }
    }
    None
}

/// A user's uid and gid from /etc/passwd.
fn ids(user: &str) -> Option<(u32, u32)> {
    let passwd = std::fs::read_to_string("/etc/passwd").ok()?;
    let line = passwd
        .lines()
        .find(|l| l.starts_with(&format!("{user}:")))?;
    let f: Vec<&str> = line.split(':').collect();
    Some((f.get(2)?.parse().ok()?, f.get(3)?.parse().ok()?))
}

/// A port nobody listens on now.
fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port()
}

fn program(name: &str) -> PathBuf {
    let sbin = Path::new("/usr/sbin").join(name);
    if sbin.is_file() {
        sbin
    } else {
        PathBuf::from(name)
    }
}

/// A single-node cluster; dropping it cancels its jobs and stops its
/// daemons (by their process ids), whatever happened.
struct Cluster {
    dir: tempfile::TempDir,
    conf: PathBuf,
    daemons: Vec<(&'static str, Child)>,
}

impl Cluster {
    fn start(node_mb: u32) -> Cluster {
        let dir = tempfile::tempdir().unwrap();
        // munged runs as munge: it must reach its folder.
        std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
        let d = dir.path();
        let munge = d.join("munge");
        std::fs::create_dir(&munge).unwrap();
        let (uid, gid) = ids("munge").expect("the munge user (apt-get install munge)");
        std::os::unix::fs::chown(&munge, Some(uid), Some(gid)).unwrap();
        for sub in ["state", "spool", "jobs"] {
            std::fs::create_dir(d.join(sub)).unwrap();
        }
        let host = std::fs::read_to_string("/proc/sys/kernel/hostname")
            .unwrap()
            .trim()
            .split('.')
            .next()
            .unwrap()
            .to_string();
        let sock = munge.join("munge.socket");
        let p = |s: &str| d.join(s).display().to_string();
        let conf = format!(
            "ClusterName=roughtui{pid}\n\
             SlurmctldHost={host}\n\
             SlurmctldPort={ctld}\n\
             SlurmdPort={slurmd}\n\
             SlurmUser=root\n\
             SlurmdUser=root\n\
             AuthType=auth/munge\n\
             AuthInfo=socket={sock}\n\
             CredType=cred/munge\n\
             StateSaveLocation={state}\n\
             SlurmdSpoolDir={spool}\n\
             SlurmctldPidFile={ctldpid}\n\
             SlurmdPidFile={slurmdpid}\n\
             SlurmctldLogFile={ctldlog}\n\
             SlurmdLogFile={slurmdlog}\n\
             ProctrackType=proctrack/linuxproc\n\
             TaskPlugin=task/none\n\
             SchedulerType=sched/backfill\n\
             SelectType=select/cons_tres\n\
             SelectTypeParameters=CR_Core_Memory\n\
             SlurmdParameters=config_overrides\n\
             ReturnToService=2\n\
             MpiDefault=none\n\
             JobCompType=jobcomp/none\n\
             AccountingStorageType=accounting_storage/none\n\
             NodeName={host} CPUs=2 RealMemory={node_mb} State=UNKNOWN\n\
             PartitionName=debug Nodes={host} Default=YES MaxTime=INFINITE State=UP\n",
            pid = std::process::id(),
            ctld = free_port(),
            slurmd = free_port(),
            sock = sock.display(),
            state = p("state"),
            spool = p("spool"),
            ctldpid = p("slurmctld.pid"),
            slurmdpid = p("slurmd.pid"),
            ctldlog = p("slurmctld.log"),
            slurmdlog = p("slurmd.log"),
        );
        let conf_path = d.join("slurm.conf");
        std::fs::write(&conf_path, conf).unwrap();
        let mut cluster = Cluster {
            dir,
            conf: conf_path,
            daemons: vec![],
        };
        let m = munge.display().to_string();
        let munged = Command::new(program("munged"))
            .args([
                "-F",
                &format!("--socket={}", sock.display()),
                &format!("--pid-file={m}/munged.pid"),
                &format!("--log-file={m}/munged.log"),
                &format!("--seed-file={m}/munged.seed"),
            ])
            .uid(uid)
            .gid(gid)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("munged");
        cluster.daemons.push(("munged", munged));
        cluster.wait_for("munged's socket", || sock.exists());
        for name in ["slurmctld", "slurmd"] {
            let child = Command::new(program(name))
                .args(["-D", "-f"])
                .arg(&cluster.conf)
                .env("SLURM_CONF", &cluster.conf)
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .expect(name);
            cluster.daemons.push((name, child));
        }
        cluster.wait_for("the node to be idle", || {
            let out = cluster.run("sinfo", &["-h", "-o", "%t"]);
            String::from_utf8_lossy(&out.stdout).contains("idle")
        });
        cluster
    }

    fn dir(&self) -> &Path {
        self.dir.path()
    }

    /// A SLURM command against this cluster, in its folder.
    fn command(&self, bin: &str) -> Command {
        let mut c = Command::new(bin);
        c.env("SLURM_CONF", &self.conf)
            .current_dir(self.dir.path().join("jobs"));
        c
    }

    fn run(&self, bin: &str, args: &[&str]) -> Output {
        self.command(bin).args(args).output().unwrap()
    }

    fn wait_for(&self, what: &str, mut done: impl FnMut() -> bool) {
        let start = Instant::now();
        while !done() {
            if start.elapsed() > Duration::from_secs(60) {
                let log = |f: &str| std::fs::read_to_string(self.dir().join(f)).unwrap_or_default();
                panic!(
                    "waited 60 s for {what}\nslurmctld.log:\n{}\nslurmd.log:\n{}",
                    log("slurmctld.log"),
                    log("slurmd.log")
                );
            }
            std::thread::sleep(Duration::from_millis(20));
        }
    }

    /// Submits `script`; its job id.
    fn sbatch(&self, script: &Path) -> String {
        let out = self.run("sbatch", &["--parsable", script.to_str().unwrap()]);
        assert!(
            out.status.success(),
            "sbatch: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout).trim().to_string()
    }

    fn wait_job(&self, job: &str) {
        self.wait_for(&format!("job {job} to end"), || {
            self.run("squeue", &["-h", "-j", job]).stdout.is_empty()
        });
    }
}

impl Drop for Cluster {
    fn drop(&mut self) {
        let _ = self.run("scancel", &["--user=root"]);
        let start = Instant::now();
        while start.elapsed() < Duration::from_secs(20)
            && !self.run("squeue", &["-h"]).stdout.is_empty()
        {
            std::thread::sleep(Duration::from_millis(100));
        }
        // The daemons it started, by their ids, the last started first.
        for (name, child) in self.daemons.iter_mut().rev() {
            let _ = Command::new("kill").arg(child.id().to_string()).status();
            let start = Instant::now();
            while start.elapsed() < Duration::from_secs(10) {
                if let Ok(Some(_)) = child.try_wait() {
                    break;
                }
                std::thread::sleep(Duration::from_millis(50));
            }
            if !matches!(child.try_wait(), Ok(Some(_))) {
                eprintln!("{name} did not stop on SIGTERM: killed");
                let _ = child.kill();
                let _ = child.wait();
            }
        }
    }
}

/// The ensemble: small grids, a few seconds a task.
const ENSEMBLE: [&str; 13] = [
    "export", "--view", "contact", "--preset", "fig2", "--set", "zeta=32", "--cell", "1",
    "--points", "4", "--seeds", "8",
];

fn roughtui(dir: &Path, args: &[&str], env: &[(&str, &Path)]) -> Output {
    let mut c = Command::new(BIN);
    c.args(args).current_dir(dir).stdin(Stdio::null());
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().unwrap()
}

fn text(out: &Output, what: &str) -> String {
    assert!(
        out.status.success(),
        "{what}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout.clone()).unwrap()
}

#[test]
fn an_ensemble_runs_as_a_job_array_and_merges_exactly() {
    if let Some(why) = missing() {
        assert!(
            std::env::var_os("ROUGHTUI_REQUIRE_SLURM").is_none_or(|v| v != "1"),
            "ROUGHTUI_REQUIRE_SLURM=1 but {why}"
        );
        eprintln!("skipped: a SLURM cluster cannot be started here: {why}");
        return;
    }
    let started = Instant::now();
    let cluster = Cluster::start(1000);
    let jobs = cluster.dir().join("jobs");
    let conf: &Path = &cluster.conf;
    let env = [("SLURM_CONF", conf)];
    // A grid the node cannot hold is refused before anything is submitted.
    let big = roughtui(
        &jobs,
        &[
            "export",
            "--view",
            "contact",
            "--preset",
            "fig2",
            "--set",
            "zeta=512",
            "--cell",
            "1",
            "--seeds",
            "4",
            "--slurm-array",
            "4",
        ],
        &env,
    );
    let err = String::from_utf8_lossy(&big.stderr);
    assert_eq!(big.status.code(), Some(2), "{err}");
    assert!(
        err.contains("the 4096 × 4096 grid needs 2162 MB a task"),
        "{err}"
    );
    assert!(
        err.contains("the largest node of this cluster has 1000 MB (sinfo)"),
        "{err}"
    );

    let script = text(
        &roughtui(
            &jobs,
            &[&ENSEMBLE[..], &["--slurm-array", "4", "--slurm-cpus", "1"]].concat(),
            &env,
        ),
        "--slurm-array",
    );
    for want in [
        "#SBATCH --array=1-4",
        "#SBATCH --cpus-per-task=1",
        "#SBATCH --mem=73M",
    ] {
        assert!(script.contains(want), "{want}:\n{script}");
    }
    let file = jobs.join("ensemble.sbatch");
    std::fs::write(&file, &script).unwrap();
    let parts = jobs.join("fig2-contact-seeds-1-8");
    let part = |k: u32| parts.join(format!("part-{k}-of-4.csv"));

    // The first submission: task 3 cancelled midway, while it writes.
    let first = cluster.sbatch(&file);
    cluster.wait_for("task 3 to start writing its part", || {
        std::fs::read_dir(&parts).is_ok_and(|d| {
            d.flatten().any(|e| {
                e.file_name()
                    .to_string_lossy()
                    .starts_with(".part-3-of-4.csv.")
            })
        })
    });
    let out = cluster.run("scancel", &[&format!("{first}_3")]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    cluster.wait_job(&first);
    for k in [1, 2, 4] {
        assert!(part(k).is_file(), "part {k} not written");
    }
    assert!(
        !part(3).exists(),
        "the cancelled task left a finished-looking part"
    );
    let when: Vec<_> = [1, 2, 4]
        .map(|k| std::fs::metadata(part(k)).unwrap().modified().unwrap())
        .to_vec();
    let log = |job: &str, k: u32| {
        std::fs::read_to_string(jobs.join(format!("roughtui-fig2-contact-{job}_{k}.log")))
            .unwrap_or_default()
    };
    assert!(
        log(&first, 1).contains("solving on 1 threads"),
        "{}",
        log(&first, 1)
    );

    // Submitted again: only part 3 is solved.
    let again = cluster.sbatch(&file);
    cluster.wait_job(&again);
    assert!(
        part(3).is_file(),
        "part 3 not solved again: {}",
        log(&again, 3)
    );
    for (k, t) in [1, 2, 4].into_iter().zip(when) {
        assert_eq!(
            std::fs::metadata(part(k)).unwrap().modified().unwrap(),
            t,
            "part {k} rewritten"
        );
        assert!(
            log(&again, k).contains("is done already"),
            "{}",
            log(&again, k)
        );
    }
    assert!(log(&again, 3).contains("solved in"), "{}", log(&again, 3));

    // Merged: the one machine's CSV.
    let mut merge = vec!["merge".to_string()];
    merge.extend((1..=4).map(|k| part(k).display().to_string()));
    let merge: Vec<&str> = merge.iter().map(String::as_str).collect();
    let merged = text(&roughtui(&jobs, &merge, &[]), "merge");
    let one = text(&roughtui(&jobs, &ENSEMBLE, &[]), "one machine");
    // To the last digit, but for a `#` line's statistic of the seeds'
    // means.
    let d = common::merge::difference(&one, &merged);
    assert!(d <= 1e-12, "{d}");
    let rows = |t: &str| -> Vec<String> {
        t.lines()
            .filter(|l| !l.starts_with('#'))
            .map(String::from)
            .collect()
    };
    assert_eq!(rows(&merged), rows(&one));
    println!(
        "4-task array of 8 seeds (256² grids), a task cancelled and resubmitted, merged: one \
         machine's --seeds 8 (largest relative difference {d:e}); {:.1} s in all",
        started.elapsed().as_secs_f64()
    );
}
