//! Running firmware under `qemu-system-arm` (shared/research/qemu.md, "Running"): `-display
//! none` (not `-nographic`, which fails with standard input closed), semihosting with
//! `target=native`, standard input closed, output to a file (never a pipe that could close
//! early), a timeout, and the instruction-count plugin.

use std::io::{Read, Write};
use std::os::unix::net::UnixStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

/// The plugin's source, built with gcc at run time (Debian's QEMU ships no plugins).
const PLUGIN_SOURCE: &str = include_str!("instruction_count_plugin.c");

/// Builds the instruction-count plugin once per process into `directory`.
pub fn instruction_count_plugin(directory: &Path) -> Result<PathBuf, String> {
    static PLUGIN: OnceLock<Result<PathBuf, String>> = OnceLock::new();
    PLUGIN.get_or_init(|| build_plugin(directory)).clone()
}

fn build_plugin(directory: &Path) -> Result<PathBuf, String> {
    std::fs::create_dir_all(directory).map_err(|error| format!("{}: {error}", directory.display()))?;
    let source = directory.join("instruction_count_plugin.c");
    std::fs::write(&source, PLUGIN_SOURCE).map_err(|error| format!("{}: {error}", source.display()))?;
    // Build under a name of our own and rename, so that concurrent xtasks never load a
    // half-written library.
    let library = directory.join("instruction_count_plugin.so");
    let partial = directory.join(format!("instruction_count_plugin.{}.so", std::process::id()));
    let output = Command::new("gcc")
        .args(["-shared", "-fPIC", "-O2", "-Wall", "-o"])
        .arg(&partial)
        .arg(&source)
        .stdin(Stdio::null())
        .output()
        .map_err(|error| format!("cannot run gcc: {error}"))?;
    if !output.status.success() {
        return Err(format!("building the QEMU plugin failed:\n{}", String::from_utf8_lossy(&output.stderr)));
    }
    std::fs::rename(&partial, &library).map_err(|error| format!("{}: {error}", library.display()))?;
    Ok(library)
}

/// One QEMU machine as the firmware runs on it.
#[derive(Clone, Copy, Debug)]
pub struct Machine {
    pub name: &'static str,
    pub cpu: &'static str,
}

pub struct QemuRun {
    child: Child,
    started: Instant,
    timeout: Duration,
    /// QEMU's standard output and error (the firmware's semihosting text).
    pub output_path: PathBuf,
}

impl QemuRun {
    /// Starts `elf` on `machine` in `work_dir`, where semihosting files appear.
    pub fn start(
        machine: Machine,
        elf: &Path,
        work_dir: &Path,
        plugin_arguments: &str,
        monitor_socket: Option<&Path>,
        timeout: Duration,
    ) -> Result<Self, String> {
        let output_path = work_dir.join("qemu-output.txt");
        let output = std::fs::File::create(&output_path).map_err(|error| format!("{}: {error}", output_path.display()))?;
        let errors = output.try_clone().map_err(|error| error.to_string())?;
        let mut command = Command::new("qemu-system-arm");
        command
            .args(["-cpu", machine.cpu, "-machine", machine.name, "-display", "none"])
            .args(["-semihosting-config", "enable=on,target=native"])
            .arg("-kernel")
            .arg(elf)
            .arg("-plugin")
            .arg(plugin_arguments)
            .current_dir(work_dir)
            .stdin(Stdio::null())
            .stdout(output)
            .stderr(errors);
        if let Some(socket) = monitor_socket {
            command.arg("-monitor").arg(format!("unix:{},server=on,wait=off", socket.display()));
        }
        let child = command.spawn().map_err(|error| format!("cannot start qemu-system-arm: {error}"))?;
        Ok(Self { child, started: Instant::now(), timeout, output_path })
    }

    pub fn output(&self) -> String {
        std::fs::read_to_string(&self.output_path).unwrap_or_default()
    }

    fn timed_out(&self) -> bool {
        self.started.elapsed() > self.timeout
    }

    /// Kills QEMU and describes why.
    fn abandon(&mut self, why: &str) -> String {
        let _ = self.child.kill();
        let _ = self.child.wait();
        format!("{why}; QEMU's output:\n{}", self.output())
    }

    /// Waits until QEMU's output contains `text`; fails if QEMU exits first or time runs out.
    pub fn wait_for_output(&mut self, text: &str) -> Result<(), String> {
        loop {
            if self.output().contains(text) {
                return Ok(());
            }
            if let Ok(Some(status)) = self.child.try_wait() {
                return Err(format!("QEMU exited ({status}) before the firmware said {text:?}; its output:\n{}", self.output()));
            }
            if self.timed_out() {
                return Err(self.abandon(&format!("timed out after {:?} waiting for {text:?}", self.timeout)));
            }
            std::thread::sleep(Duration::from_millis(5));
        }
    }

    /// QEMU's exit status if it has exited.
    pub fn exited(&mut self) -> Result<Option<ExitStatus>, String> {
        self.child.try_wait().map_err(|error| format!("waiting for QEMU: {error}"))
    }

    /// Waits for QEMU to exit, killing it when time runs out.
    pub fn wait(&mut self) -> Result<ExitStatus, String> {
        loop {
            match self.child.try_wait() {
                Ok(Some(status)) => return Ok(status),
                Ok(None) if self.timed_out() => {
                    return Err(self.abandon(&format!("QEMU timed out after {:?}", self.timeout)));
                }
                Ok(None) => std::thread::sleep(Duration::from_millis(5)),
                Err(error) => return Err(format!("waiting for QEMU: {error}")),
            }
        }
    }
}

impl Drop for QemuRun {
    /// Never leave a QEMU behind.
    fn drop(&mut self) {
        if let Ok(None) = self.child.try_wait() {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}

/// A connection to QEMU's human monitor on a unix socket.
pub struct Monitor {
    stream: UnixStream,
}

impl Monitor {
    /// Connects, retrying while QEMU creates the socket.
    pub fn connect(socket: &Path, deadline: Duration) -> Result<Self, String> {
        let started = Instant::now();
        loop {
            match UnixStream::connect(socket) {
                Ok(stream) => {
                    stream.set_read_timeout(Some(Duration::from_secs(30))).map_err(|error| error.to_string())?;
                    let mut monitor = Self { stream };
                    monitor.read_to_prompt()?;
                    return Ok(monitor);
                }
                Err(_) if started.elapsed() < deadline => std::thread::sleep(Duration::from_millis(10)),
                Err(error) => return Err(format!("cannot reach the QEMU monitor at {}: {error}", socket.display())),
            }
        }
    }

    /// Sends one command and returns what QEMU answered before its next prompt.
    pub fn command(&mut self, command: &str) -> Result<String, String> {
        self.stream.write_all(format!("{command}\n").as_bytes()).map_err(|error| format!("monitor: {error}"))?;
        self.read_to_prompt()
    }

    fn read_to_prompt(&mut self) -> Result<String, String> {
        let mut answer = Vec::new();
        let mut buffer = [0u8; 4096];
        while !answer.ends_with(b"(qemu) ") {
            let count = self.stream.read(&mut buffer).map_err(|error| format!("monitor: {error}"))?;
            if count == 0 {
                return Err(format!("the QEMU monitor closed; it said: {}", String::from_utf8_lossy(&answer)));
            }
            answer.extend_from_slice(&buffer[..count]);
        }
        Ok(String::from_utf8_lossy(&answer).into_owned())
    }
}
