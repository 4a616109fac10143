//! The one runner behind every hostile case: spawns `qmckit` under a 4 GiB address-space
//! limit (`ulimit -v` in bash, then `exec`), feeds its standard input, reads a bounded prefix
//! of its standard output, kills it past the case's wall-clock bound, and checks the
//! contract:
//!
//! * exit 0, no panic text, every stderr line a `qmckit: ` note (not an error), and every
//!   number on stdout finite (text, or the float64/float32 data of a `.npy`); or
//! * exit 2 (or 1 where the environment fails, for cases that say so) with exactly one
//!   `qmckit: error: ` line on stderr and nothing on stdout;
//!
//! and then the case's own check (files it wrote or left alone, the shape of its output).

use std::fs::File;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// The address-space limit of every case (KiB, as `ulimit -v` takes it): 4 GiB.
pub const ADDRESS_SPACE_KIB: u64 = 4 << 20;

/// Default wall-clock bound of a case that should answer.
pub const ANSWER_TIME: Duration = Duration::from_secs(10);

/// Default wall-clock bound of a case that should refuse.
pub const REFUSAL_TIME: Duration = Duration::from_secs(5);

/// Stdout bytes kept (the pipe is closed past them: a streaming command then ends on a
/// broken pipe, which is exit 0).
pub const STDOUT_CAP: usize = 8 << 20;

/// Stderr bytes kept (the rest is read and dropped, so the child never blocks on it).
const STDERR_CAP: usize = 64 << 10;

/// What the command's standard input is.
pub enum Input {
    /// Empty (`/dev/null`).
    Empty,
    /// These bytes, through a pipe.
    Bytes(Vec<u8>),
    /// `pattern` repeated `times` times, written through a pipe by a thread (gigabytes of
    /// generated text without a file).
    Repeat(&'static [u8], usize),
    /// A file opened for reading: an absolute path, or one relative to the case directory.
    File(&'static str),
}

/// The exits a case accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expect {
    /// Exit 0 with finite output.
    Answer,
    /// Exit 2, one line.
    Refuse,
    /// Either of the two.
    AnswerOrRefuse,
    /// Exit 1 or 2, one line: the environment failed (an unwritable output) or the request
    /// was refused.
    Fail,
}

/// One run's result, for the case's own check.
pub struct Run {
    /// The exit code (a signal has none; the runner fails that first).
    pub code: i32,
    /// Stdout, at most [`STDOUT_CAP`] bytes.
    pub stdout: Vec<u8>,
    /// Whether stdout was cut at the cap.
    pub truncated: bool,
    /// Stderr, lossily decoded.
    pub stderr: String,
    /// The case's private directory (its working directory too).
    pub dir: PathBuf,
}

/// The case's own check: `Err` with a reason fails it.
pub type Check = fn(&Run) -> Result<(), String>;

/// Prepares the case directory before the run (input files, an earlier figure).
pub type Setup = fn(&Path);

/// One hostile invocation, as data.
pub struct Case {
    /// Arguments after `qmckit`; `{dir}` becomes the case directory.
    pub args: &'static [&'static str],
    /// Standard input.
    pub input: Input,
    /// Extra environment.
    pub env: &'static [(&'static str, &'static str)],
    /// The exits accepted.
    pub expect: Expect,
    /// Wall-clock bound (the child is killed past it and the case fails); `None`: the
    /// default of [`ANSWER_TIME`] or [`REFUSAL_TIME`].
    pub limit: Option<Duration>,
    /// Runs before the command.
    pub setup: Option<Setup>,
    /// Runs after the contract holds.
    pub check: Option<Check>,
    /// Run as an unprivileged user (nobody) when the suite runs as root, so that file
    /// permissions apply (a read-only directory).
    pub unprivileged: bool,
}

impl Case {
    /// A case with empty input, no environment, default bound, no setup or check.
    pub const fn new(args: &'static [&'static str], expect: Expect) -> Self {
        Case {
            args,
            input: Input::Empty,
            env: &[],
            expect,
            limit: None,
            setup: None,
            check: None,
            unprivileged: false,
        }
    }

    pub fn stdin(mut self, bytes: impl Into<Vec<u8>>) -> Self {
        self.input = Input::Bytes(bytes.into());
        self
    }

    pub fn input(mut self, input: Input) -> Self {
        self.input = input;
        self
    }

    pub fn env(mut self, env: &'static [(&'static str, &'static str)]) -> Self {
        self.env = env;
        self
    }

    pub fn within(mut self, secs: f64) -> Self {
        self.limit = Some(Duration::from_secs_f64(secs));
        self
    }

    pub fn setup(mut self, setup: Setup) -> Self {
        self.setup = Some(setup);
        self
    }

    pub fn check(mut self, check: Check) -> Self {
        self.check = Some(check);
        self
    }

    pub fn unprivileged(mut self) -> Self {
        self.unprivileged = true;
        self
    }
}

/// A fresh private directory for case `name`.
fn case_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("qmckit-hostile-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("case directory");
    dir
}

/// Reads `pipe` to its end, keeping at most `cap` bytes; with `close_at_cap`, stops and
/// drops the pipe at the cap instead (the writer then sees a broken pipe).
fn reader(
    mut pipe: impl Read + Send + 'static,
    cap: usize,
    close_at_cap: bool,
) -> JoinHandle<(Vec<u8>, bool)> {
    std::thread::spawn(move || {
        let mut kept = Vec::new();
        let mut buf = vec![0u8; 64 << 10];
        let mut truncated = false;
        loop {
            match pipe.read(&mut buf) {
                Ok(0) | Err(_) => break,
                Ok(k) => {
                    let room = cap - kept.len();
                    kept.extend_from_slice(&buf[..k.min(room)]);
                    if k >= room {
                        truncated = true;
                        if close_at_cap {
                            break;
                        }
                    }
                }
            }
        }
        (kept, truncated)
    })
}

/// Text that can hide a crash behind an exit code.
const CRASH_TEXT: [&str; 6] = [
    "panicked",
    "RUST_BACKTRACE",
    "stack backtrace",
    "memory allocation of",
    "has overflowed its stack",
    "fatal runtime error",
];

/// Whether this process runs as root (`Uid:` of /proc/self/status).
fn is_root() -> bool {
    std::fs::read_to_string("/proc/self/status").is_ok_and(|s| {
        s.lines()
            .find_map(|l| l.strip_prefix("Uid:"))
            .and_then(|ids| ids.split_whitespace().nth(1))
            == Some("0")
    })
}

fn spawn(case: &Case, dir: &Path) -> Result<Child, String> {
    let mut command = if case.unprivileged && is_root() {
        let mut c = Command::new("setpriv");
        c.args(["--reuid=65534", "--regid=65534", "--clear-groups", "bash"]);
        c
    } else {
        Command::new("bash")
    };
    command
        .arg("-c")
        .arg(format!(
            "ulimit -v {ADDRESS_SPACE_KIB} || exit 99; exec \"$0\" \"$@\""
        ))
        .arg(env!("CARGO_BIN_EXE_qmckit"))
        .args(
            case.args
                .iter()
                .map(|a| a.replace("{dir}", dir.to_str().unwrap())),
        )
        .current_dir(dir)
        .env_remove("RUST_BACKTRACE")
        .env_remove("RAYON_NUM_THREADS")
        .envs(case.env.iter().copied())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    match &case.input {
        Input::Empty => {
            command.stdin(Stdio::null());
        }
        Input::File(path) => {
            let file = File::open(dir.join(path)).map_err(|e| format!("stdin {path}: {e}"))?;
            command.stdin(Stdio::from(file));
        }
        Input::Bytes(_) | Input::Repeat(..) => {
            command.stdin(Stdio::piped());
        }
    }
    command.spawn().map_err(|e| format!("spawn: {e}"))
}

/// Feeds piped input from a thread (a command that stops reading closes the pipe: not the
/// case's concern).
fn feed(child: &mut Child, input: &Input) -> Option<JoinHandle<()>> {
    let mut stdin = child.stdin.take()?;
    let job: Box<dyn FnOnce() + Send> = match input {
        Input::Bytes(bytes) => {
            let bytes = bytes.clone();
            Box::new(move || {
                let _ = stdin.write_all(&bytes);
            })
        }
        &Input::Repeat(pattern, times) => Box::new(move || {
            let per = (1 << 20) / pattern.len().max(1);
            let chunk = pattern.repeat(per.max(1));
            let mut left = times;
            while left > 0 {
                let k = left.min(per.max(1));
                if stdin.write_all(&chunk[..k * pattern.len()]).is_err() {
                    return;
                }
                left -= k;
            }
        }),
        _ => return None,
    };
    Some(std::thread::spawn(job))
}

/// Runs `case` in its own directory; `Err` says how it broke the contract.
pub fn run_case(name: &str, case: Case) -> Result<(), String> {
    let dir = case_dir(name);
    if let Some(setup) = case.setup {
        setup(&dir);
    }
    let limit = case.limit.unwrap_or(match case.expect {
        Expect::Answer | Expect::AnswerOrRefuse => ANSWER_TIME,
        Expect::Refuse | Expect::Fail => REFUSAL_TIME,
    });
    let clock = Instant::now();
    let mut child = spawn(&case, &dir)?;
    let writer = feed(&mut child, &case.input);
    let out = reader(child.stdout.take().unwrap(), STDOUT_CAP, true);
    let err = reader(child.stderr.take().unwrap(), STDERR_CAP, false);
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            break status;
        }
        if clock.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            let (stderr, _) = err.join().unwrap();
            return Err(format!(
                "still running after {limit:?} (killed); stderr: {:?}",
                String::from_utf8_lossy(&stderr)
            ));
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let took = clock.elapsed();
    // Shown with --nocapture (and for failures): how close each case runs to its bound.
    eprintln!(
        "{name}: exit {:?} in {:.2} s (bound {:.1} s)",
        status.code(),
        took.as_secs_f64(),
        limit.as_secs_f64()
    );
    let (stdout, truncated) = out.join().unwrap();
    let (stderr, _) = err.join().unwrap();
    if let Some(writer) = writer {
        let _ = writer.join();
    }
    let stderr = String::from_utf8_lossy(&stderr).into_owned();
    let run = Run {
        code: status.code().unwrap_or(-1),
        stdout,
        truncated,
        stderr,
        dir: dir.clone(),
    };
    let verdict = contract(&case, &run, status.code().is_none(), took).and_then(|()| {
        case.check
            .map_or(Ok(()), |check| check(&run))
            .map_err(|e| format!("{e} (exit {}, stderr {:?})", run.code, run.stderr))
    });
    if verdict.is_ok() {
        // Make read-only directories removable again.
        let _ = Command::new("chmod")
            .arg("-R")
            .arg("u+w")
            .arg(&dir)
            .status();
        let _ = std::fs::remove_dir_all(&dir);
    }
    verdict
}

/// The contract every case keeps, whatever it asks.
fn contract(case: &Case, run: &Run, signalled: bool, took: Duration) -> Result<(), String> {
    let err = &run.stderr;
    if signalled {
        return Err(format!(
            "killed by a signal after {took:?}; stderr: {err:?}"
        ));
    }
    if run.code == 99 {
        return Err("could not set the address-space limit".into());
    }
    if let Some(bad) = CRASH_TEXT.iter().find(|t| err.contains(*t)) {
        return Err(format!("crash text {bad:?} on stderr: {err:?}"));
    }
    let lines: Vec<&str> = err.lines().collect();
    let accepted = match case.expect {
        Expect::Answer => run.code == 0,
        Expect::Refuse => run.code == 2,
        Expect::AnswerOrRefuse => run.code == 0 || run.code == 2,
        Expect::Fail => run.code == 1 || run.code == 2,
    };
    if !accepted {
        return Err(format!(
            "exit {} where {:?} was expected; stderr: {err:?}",
            run.code, case.expect
        ));
    }
    if run.code == 0 {
        if let Some(l) = lines
            .iter()
            .find(|l| !l.starts_with("qmckit: ") || l.starts_with("qmckit: error"))
        {
            return Err(format!(
                "exit 0 with an error or stray line on stderr: {l:?}"
            ));
        }
        finite_output(&run.stdout, run.truncated)?;
    } else {
        if lines.len() != 1 || !lines[0].starts_with("qmckit: error: ") {
            return Err(format!(
                "exit {} needs exactly one 'qmckit: error: ' line on stderr, got {err:?}",
                run.code
            ));
        }
        if !run.stdout.is_empty() {
            return Err(format!(
                "exit {} after writing {} bytes to stdout (a partial answer)",
                run.code,
                run.stdout.len()
            ));
        }
    }
    Ok(())
}

/// Every number on stdout is finite: text tokens (split at whitespace, commas, `;`, `=`,
/// brackets) that parse as f64, or the values of a `.npy` (float64 or float32, little
/// endian). Other binary output (PNG) is not looked into. A cut-off last line is skipped.
pub fn finite_output(bytes: &[u8], truncated: bool) -> Result<(), String> {
    if bytes.starts_with(b"\x93NUMPY") {
        return finite_npy(bytes, truncated);
    }
    let Ok(text) = std::str::from_utf8(bytes).or_else(|e| {
        if truncated {
            std::str::from_utf8(&bytes[..e.valid_up_to()])
        } else {
            Err(e)
        }
    }) else {
        return Ok(()); // binary (PNG): its own check looks into it
    };
    let text = if truncated {
        &text[..text.rfind('\n').map_or(0, |k| k + 1)]
    } else {
        text
    };
    finite_text(text)
}

/// Every token of `text` that parses as f64 is finite.
pub fn finite_text(text: &str) -> Result<(), String> {
    for (k, line) in text.lines().enumerate() {
        for token in line.split(|c: char| {
            c.is_whitespace() || matches!(c, ',' | ';' | '=' | '(' | ')' | '[' | ']' | ':')
        }) {
            if let Ok(x) = token.parse::<f64>()
                && !x.is_finite()
            {
                return Err(format!("line {}: non-finite {token:?} in {line:?}", k + 1));
            }
        }
    }
    Ok(())
}

/// The data of a `.npy` of float64 or float32 values is finite.
fn finite_npy(bytes: &[u8], truncated: bool) -> Result<(), String> {
    if bytes.len() < 10 {
        return Err("a .npy shorter than its preamble".into());
    }
    let (len, start) = if bytes[6] == 1 {
        (u16::from_le_bytes([bytes[8], bytes[9]]) as usize, 10)
    } else {
        if bytes.len() < 12 {
            return Err("a .npy shorter than its preamble".into());
        }
        (
            u32::from_le_bytes(bytes[8..12].try_into().unwrap()) as usize,
            12,
        )
    };
    let Some(header) = bytes.get(start..start + len) else {
        return Err("a .npy cut inside its header".into());
    };
    let header = String::from_utf8_lossy(header);
    let data = &bytes[start + len..];
    let values: Vec<f64> = if header.contains("<f8") {
        data.chunks_exact(8)
            .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
            .collect()
    } else if header.contains("<f4") {
        data.chunks_exact(4)
            .map(|c| f64::from(f32::from_le_bytes(c.try_into().unwrap())))
            .collect()
    } else {
        return Ok(());
    };
    if !truncated && !data.len().is_multiple_of(8) && header.contains("<f8") {
        return Err(format!("a .npy with {} data bytes", data.len()));
    }
    match values.iter().position(|x| !x.is_finite()) {
        Some(k) => Err(format!("a .npy value {} at {k}", values[k])),
        None => Ok(()),
    }
}

/// Whether `text` is well-formed XML as far as an SVG needs: only characters XML allows,
/// balanced tags, quoted attributes, and `&` only in entities.
pub fn well_formed_xml(text: &str) -> Result<(), String> {
    if let Some(c) = text.chars().find(|&c| {
        (c < ' ' && !matches!(c, '\t' | '\n' | '\r')) || c == '\u{fffe}' || c == '\u{ffff}'
    }) {
        return Err(format!("character {c:?} is not allowed in XML"));
    }
    let mut stack: Vec<&str> = Vec::new();
    let mut rest = text;
    while let Some(open) = rest.find('<') {
        entities(&rest[..open])?;
        rest = &rest[open..];
        if let Some(body) = rest.strip_prefix("<!--") {
            let end = body.find("-->").ok_or("an unclosed comment")?;
            rest = &body[end + 3..];
            continue;
        }
        if let Some(body) = rest.strip_prefix("<![CDATA[") {
            let end = body.find("]]>").ok_or("an unclosed CDATA section")?;
            rest = &body[end + 3..];
            continue;
        }
        if rest.starts_with("<?") || rest.starts_with("<!") {
            let end = rest.find('>').ok_or("an unclosed declaration")?;
            rest = &rest[end + 1..];
            continue;
        }
        // A tag: find its end outside quoted attribute values.
        let mut quote = None;
        let mut end = None;
        for (k, c) in rest.char_indices().skip(1) {
            match (quote, c) {
                (None, '"' | '\'') => quote = Some(c),
                (Some(q), c) if c == q => quote = None,
                (None, '<') => return Err("'<' inside a tag".into()),
                (Some(_), '<') => return Err("'<' inside an attribute value".into()),
                (None, '>') => {
                    end = Some(k);
                    break;
                }
                _ => {}
            }
        }
        let end = end.ok_or("an unclosed tag")?;
        let tag = &rest[1..end];
        rest = &rest[end + 1..];
        entities(tag)?;
        if let Some(name) = tag.strip_prefix('/') {
            let name = name.trim();
            match stack.pop() {
                Some(open) if open == name => {}
                other => return Err(format!("</{name}> closes {other:?}")),
            }
        } else if !tag.ends_with('/') {
            let name = tag.split(|c: char| c.is_whitespace()).next().unwrap_or("");
            if name.is_empty() {
                return Err("a tag without a name".into());
            }
            stack.push(name);
        }
    }
    entities(rest)?;
    if !stack.is_empty() {
        return Err(format!("unclosed elements {stack:?}"));
    }
    if !text.trim_start().starts_with("<svg") && !text.trim_start().starts_with("<?xml") {
        return Err("not an SVG document".into());
    }
    Ok(())
}

/// Every `&` in `text` starts an entity (`&name;`, or `&#N;` / `&#xH;` of a character XML
/// allows).
fn entities(text: &str) -> Result<(), String> {
    let mut rest = text;
    while let Some(k) = rest.find('&') {
        rest = &rest[k + 1..];
        let end = rest.find(';').ok_or("a bare '&'")?;
        let name = &rest[..end];
        let ok = match name.strip_prefix('#') {
            Some(n) => n
                .strip_prefix('x')
                .map_or_else(|| n.parse::<u32>().ok(), |h| u32::from_str_radix(h, 16).ok())
                .is_some_and(|c| {
                    matches!(c, 0x9 | 0xa | 0xd | 0x20..=0xd7ff | 0xe000..=0xfffd | 0x10000..=0x10ffff)
                }),
            None => !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric()),
        };
        if !ok {
            return Err(format!(
                "a bare '&' or a reference to a character XML forbids: &{name};"
            ));
        }
    }
    Ok(())
}
