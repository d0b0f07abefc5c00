//! Atomic file output shared by every tier: a result file is either the old one or the complete
//! new one, never half-written.

use std::io::Write;
use std::path::{Path, PathBuf};

/// Temporary sibling of `path` (`name.<pid>.tmp`) used while writing it.
pub fn tmp_path(path: &Path) -> PathBuf {
    let mut name = path
        .file_name()
        .map(|n| n.to_os_string())
        .unwrap_or_default();
    name.push(format!(".{}.tmp", std::process::id()));
    path.with_file_name(name)
}

/// Writes `bytes` to `path`: to a temporary sibling, fsync, then rename over `path`.
///
/// Creates missing parent directories. When `path` already exists and is not a regular file
/// (`/dev/null`, `/dev/stdout`, a FIFO), the bytes are written straight into it instead: renaming
/// over a device would replace it with a regular file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    if let Ok(meta) = std::fs::metadata(path) {
        if !meta.is_file() && !meta.is_dir() {
            let mut f = std::fs::OpenOptions::new().write(true).open(path)?;
            f.write_all(bytes)?;
            return f.flush();
        }
    }
    if let Some(dir) = path.parent() {
        if !dir.as_os_str().is_empty() {
            std::fs::create_dir_all(dir)?;
        }
    }
    let tmp = tmp_path(path);
    let written = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()
    })();
    if let Err(e) = written.and_then(|_| std::fs::rename(&tmp, path)) {
        let _ = std::fs::remove_file(&tmp);
        return Err(e);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replaces_a_regular_file_whole() {
        let dir = std::env::temp_dir().join(format!("superlube-atomic-{}", std::process::id()));
        let p = dir.join("sub/out.csv");
        write_atomic(&p, b"first, longer content\n").unwrap();
        write_atomic(&p, b"second\n").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"second\n");
        assert!(!tmp_path(&p).exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn writing_to_dev_null_keeps_it_a_device() {
        use std::os::unix::fs::FileTypeExt;
        let null = Path::new("/dev/null");
        if !std::fs::metadata(null).is_ok_and(|m| m.file_type().is_char_device()) {
            return; // broken environment; nothing to protect
        }
        write_atomic(null, b"discarded\n").unwrap();
        let m = std::fs::metadata(null).unwrap();
        assert!(m.file_type().is_char_device(), "/dev/null was replaced");
    }
}
