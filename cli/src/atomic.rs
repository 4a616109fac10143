//! Atomic outputs: every file the tool writes goes to a temporary file beside its target and
//! is renamed over it only once it is complete, and a directory of outputs (the report) is
//! assembled in a temporary directory and moved into place. On any failure the user's files
//! are unchanged and no partial file is left behind.

use std::fs::{self, File, OpenOptions};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicU32, Ordering};

use super::Failure;

/// The temporary files and directories of outputs in progress, removed by
/// [`remove_pending`] when the process is interrupted (SIGINT, SIGTERM, SIGHUP), so that a
/// killed command leaves nothing behind.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Records a temporary path as in progress.
fn pending(path: &Path) {
    if let Ok(mut p) = PENDING.lock() {
        p.push(path.to_path_buf());
    }
}

/// Forgets a temporary path (renamed into place or removed).
fn settled(path: &Path) {
    if let Ok(mut p) = PENDING.lock() {
        p.retain(|q| q != path);
    }
}

/// Removes every temporary output in progress; called by the termination handler
/// ([`on_termination`]) before the process exits.
pub fn remove_pending() {
    let paths = match PENDING.lock() {
        Ok(mut p) => std::mem::take(&mut *p),
        Err(_) => return,
    };
    for path in paths {
        // A directory still being written into may gain a file while it is removed: retry.
        for _ in 0..3 {
            let gone = if path.is_dir() {
                fs::remove_dir_all(&path).is_ok()
            } else {
                fs::remove_file(&path).is_ok()
            };
            if gone || !path.exists() {
                break;
            }
        }
    }
}

/// Installs the handler that, on SIGINT, SIGTERM or SIGHUP, removes the temporary outputs
/// in progress, prints one line and exits with status 130 (the user's files are as they
/// were: nothing was renamed over them). Installing twice is harmless (the second is
/// refused and ignored).
pub fn on_termination() {
    let _ = ctrlc::set_handler(|| {
        remove_pending();
        eprintln!("qmckit: interrupted; no output was written");
        std::process::exit(130);
    });
}

/// A failure of the environment (exit code 1) about `path`.
fn env_failure(path: &Path, what: &str, e: std::io::Error) -> Failure {
    Failure {
        code: 1,
        message: format!("{}: {what}: {e}", shown(path)),
    }
}

/// The path as errors show it: quoted when it holds a control character (one line).
pub fn shown(path: &Path) -> String {
    let s = path.display().to_string();
    if s.chars().any(char::is_control) {
        format!("{s:?}")
    } else {
        s
    }
}

/// `--out` checked where it enters: not empty.
///
/// # Errors
/// A usage failure naming `option` for an empty path.
pub fn out_path(option: &str, path: &Path) -> Result<(), Failure> {
    if path.as_os_str().is_empty() {
        return Err(Failure::usage(format!("{option} is empty: name a file")));
    }
    Ok(())
}

/// A fresh name beside `target`: `.NAME.qmckit-tmp-PID-K` in the same directory, so the
/// final rename stays within one file system.
fn sibling(target: &Path, tag: &str) -> PathBuf {
    static COUNTER: AtomicU32 = AtomicU32::new(0);
    let k = COUNTER.fetch_add(1, Ordering::Relaxed);
    let name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "out".to_owned());
    let dir = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    dir.join(format!(".{name}.qmckit-{tag}-{}-{k}", std::process::id()))
}

/// Writes the file `path` atomically: `write` fills a buffered temporary file beside it,
/// which is flushed, synced and renamed over `path` only if `write` succeeds.
///
/// # Errors
/// The failure of `write`, or an environment failure (exit 1) creating, writing or renaming
/// the file; in every case `path` is as it was and the temporary file is removed.
pub fn write_with(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> Result<(), Failure>,
) -> Result<(), Failure> {
    out_path("the output path", path)?;
    if path.is_dir() {
        return Err(Failure::usage(format!(
            "{}: is a directory, not a file",
            shown(path)
        )));
    }
    let tmp = sibling(path, "tmp");
    pending(&tmp);
    let file = match OpenOptions::new().write(true).create_new(true).open(&tmp) {
        Ok(f) => f,
        Err(e) => {
            settled(&tmp);
            return Err(env_failure(path, "cannot create a file beside it", e));
        }
    };
    let mut out = BufWriter::new(file);
    let result = write(&mut out)
        .and_then(|()| {
            out.flush()
                .map_err(|e| env_failure(path, "write failed", e))
        })
        .and_then(|()| {
            out.get_ref()
                .sync_all()
                .map_err(|e| env_failure(path, "write failed", e))
        })
        .and_then(|()| {
            fs::rename(&tmp, path).map_err(|e| env_failure(path, "cannot replace it", e))
        });
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    settled(&tmp);
    result
}

/// Writes `bytes` to `path` atomically (see [`write_with`]).
///
/// # Errors
/// As [`write_with`].
pub fn write_bytes(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    write_with(path, |out| {
        out.write_all(bytes)
            .map_err(|e| env_failure(path, "write failed", e))
    })
}

/// The name of the marker file that identifies a directory written by [`StagedDir`].
pub const MARKER: &str = ".qmckit-output";

/// A directory of outputs assembled out of sight and moved into place by
/// [`StagedDir::commit`]; dropped without committing, it is removed.
///
/// The target must not exist, be an empty directory, or be a directory this tool wrote
/// before (it holds [`MARKER`]); anything else is refused before any work is done, so a
/// user's directory is never written into.
pub struct StagedDir {
    target: PathBuf,
    tmp: PathBuf,
    committed: bool,
}

impl StagedDir {
    /// Checks `target` and creates the temporary directory beside it.
    ///
    /// # Errors
    /// A usage failure for an empty path, a file, or a directory that holds anything but an
    /// earlier output of this tool; an environment failure creating the temporary directory.
    pub fn new(option: &str, target: &Path) -> Result<Self, Failure> {
        out_path(option, target)?;
        if target.exists() {
            if !target.is_dir() {
                return Err(Failure::usage(format!(
                    "{option} {}: exists and is not a directory",
                    shown(target)
                )));
            }
            let empty = fs::read_dir(target)
                .map_err(|e| env_failure(target, "cannot read it", e))?
                .next()
                .is_none();
            if !empty && !target.join(MARKER).is_file() {
                return Err(Failure::usage(format!(
                    "{option} {}: a directory that holds files not written by qmckit; \
                     name a new or empty directory",
                    shown(target)
                )));
            }
        }
        if let Some(parent) = target.parent().filter(|p| !p.as_os_str().is_empty()) {
            fs::create_dir_all(parent).map_err(|e| env_failure(parent, "cannot create it", e))?;
        }
        let tmp = sibling(target, "tmp");
        pending(&tmp);
        if let Err(e) = fs::create_dir(&tmp) {
            settled(&tmp);
            return Err(env_failure(
                target,
                "cannot create a directory beside it",
                e,
            ));
        }
        Ok(StagedDir {
            target: target.to_path_buf(),
            tmp,
            committed: false,
        })
    }

    /// The temporary directory to write into.
    pub fn path(&self) -> &Path {
        &self.tmp
    }

    /// Marks the directory as this tool's and moves it into place (an earlier output there
    /// is replaced as a whole).
    ///
    /// # Errors
    /// An environment failure; the earlier output, if any, is then left in place.
    pub fn commit(mut self) -> Result<(), Failure> {
        fs::write(self.tmp.join(MARKER), b"written by qmckit\n")
            .map_err(|e| env_failure(&self.tmp, "write failed", e))?;
        let old = if self.target.exists() {
            let old = sibling(&self.target, "old");
            fs::rename(&self.target, &old)
                .map_err(|e| env_failure(&self.target, "cannot replace it", e))?;
            Some(old)
        } else {
            None
        };
        if let Err(e) = fs::rename(&self.tmp, &self.target) {
            if let Some(old) = &old {
                let _ = fs::rename(old, &self.target);
            }
            return Err(env_failure(
                &self.target,
                "cannot move the output into place",
                e,
            ));
        }
        self.committed = true;
        settled(&self.tmp);
        if let Some(old) = old {
            let _ = fs::remove_dir_all(old);
        }
        Ok(())
    }
}

impl Drop for StagedDir {
    fn drop(&mut self) {
        if !self.committed {
            let _ = fs::remove_dir_all(&self.tmp);
            settled(&self.tmp);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("qmckit-atomic-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn a_failed_write_leaves_the_old_file_and_no_temporary() {
        let d = scratch("file");
        let f = d.join("fig.svg");
        fs::write(&f, b"old").unwrap();
        let r = write_with(&f, |out| {
            out.write_all(b"partial").unwrap();
            Err(Failure::usage("stopped"))
        });
        assert!(r.is_err());
        assert_eq!(fs::read(&f).unwrap(), b"old");
        assert_eq!(fs::read_dir(&d).unwrap().count(), 1);
        write_bytes(&f, b"new").unwrap();
        assert_eq!(fs::read(&f).unwrap(), b"new");
        assert_eq!(fs::read_dir(&d).unwrap().count(), 1);
        assert!(write_bytes(Path::new(""), b"x").is_err());
        assert!(write_bytes(&d, b"x").is_err());
        fs::remove_dir_all(d).unwrap();
    }

    #[test]
    fn a_staged_directory_never_writes_into_a_users_directory() {
        let d = scratch("dir");
        let user = d.join("mine");
        fs::create_dir(&user).unwrap();
        fs::write(user.join("index.html"), b"mine").unwrap();
        assert!(StagedDir::new("--out", &user).is_err());
        assert!(StagedDir::new("--out", Path::new("")).is_err());
        let out = d.join("report");
        {
            let s = StagedDir::new("--out", &out).unwrap();
            fs::write(s.path().join("index.html"), b"1").unwrap();
            // dropped without commit: nothing appears
        }
        assert!(!out.exists());
        let s = StagedDir::new("--out", &out).unwrap();
        fs::write(s.path().join("index.html"), b"1").unwrap();
        s.commit().unwrap();
        let s = StagedDir::new("--out", &out).unwrap();
        fs::write(s.path().join("index.html"), b"2").unwrap();
        s.commit().unwrap();
        assert_eq!(fs::read(out.join("index.html")).unwrap(), b"2");
        assert_eq!(fs::read(user.join("index.html")).unwrap(), b"mine");
        // only the user's directory and the report remain
        assert_eq!(fs::read_dir(&d).unwrap().count(), 2);
        fs::remove_dir_all(d).unwrap();
    }
}
