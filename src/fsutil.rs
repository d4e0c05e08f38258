//! Files written whole or not at all: the content goes to a temporary file beside the target
//! (same directory, so that the rename stays on one file system), which is then renamed over
//! the target; on failure the temporary file is removed and the target is untouched. The one
//! temporary-name convention is `dir/.name.tmp<pid>.ext` (hidden, unique per process, same
//! extension, so writers that choose a format by extension still see it).
//!
//! # Accuracy
//!
//! Not numeric; the unit tests here check that a failed write leaves the target unchanged and no
//! temporary file behind.
//!
//! # Cost
//!
//! One extra rename per file.
//!
//! ```
//! let path = std::env::temp_dir().join(format!("boltzone-doc-{}.txt", std::process::id()));
//! boltzone::fsutil::write_atomic(&path, b"r,p\n")?;
//! assert_eq!(std::fs::read(&path)?, b"r,p\n");
//! std::fs::remove_file(&path)?;
//! # Ok::<(), std::io::Error>(())
//! ```

use std::io::Write;
use std::path::{Path, PathBuf};

/// `dir/.name.tmp<pid>.ext` beside `path`.
pub fn temp_path(path: &Path) -> PathBuf {
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("out");
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("tmp");
    path.with_file_name(format!(".{name}.tmp{}.{ext}", std::process::id()))
}

/// Produces the file at a temporary path by `produce(temp)`, then renames it to `path` (a
/// failed rename becomes an error by `io`); on any error the temporary file is removed and
/// `path` is left as it was.
pub fn replace_with<E>(
    path: &Path,
    produce: impl FnOnce(&Path) -> Result<(), E>,
    io: impl FnOnce(std::io::Error) -> E,
) -> Result<(), E> {
    let tmp = temp_path(path);
    let result = produce(&tmp).and_then(|()| std::fs::rename(&tmp, path).map_err(io));
    if result.is_err() {
        // best effort: the temporary file may not exist
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Writes the file through a buffered writer given to `write`, atomically ([`replace_with`]).
pub fn write_atomic_with<E: From<std::io::Error>>(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> Result<(), E>,
) -> Result<(), E> {
    replace_with(
        path,
        |tmp| {
            let mut f = std::io::BufWriter::new(std::fs::File::create(tmp)?);
            write(&mut f)?;
            f.flush()?;
            Ok(())
        },
        E::from,
    )
}

/// Writes `bytes` to `path` atomically ([`replace_with`]).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    replace_with(path, |tmp| std::fs::write(tmp, bytes), |e| e)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_write_leaves_the_target_and_no_temporary_file() {
        let dir = std::env::temp_dir().join(format!("boltzone-fsutil-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("curve.csv");
        write_atomic(&path, b"old").unwrap();
        let failed: std::io::Result<()> = write_atomic_with(&path, |w| {
            w.write_all(b"half")?;
            Err(std::io::Error::other("stopped"))
        });
        assert!(failed.is_err());
        assert_eq!(std::fs::read(&path).unwrap(), b"old");
        assert!(!temp_path(&path).exists());
        write_atomic_with(&path, |w| w.write_all(b"new")).unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"new");
        assert_eq!(
            temp_path(&path).file_name().and_then(|n| n.to_str()),
            Some(format!(".curve.csv.tmp{}.csv", std::process::id()).as_str())
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
