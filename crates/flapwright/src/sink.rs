//! Where a design's files go: the library renders bytes and hands them to a [`Sink`]; the
//! command line's staging folder is one sink, [`MemorySink`] another (the benches, the
//! example and any program that wants the files in memory).

use std::collections::BTreeMap;
use std::io;
use std::sync::Mutex;

/// Takes the files of a design, each by its name relative to the output folder.
pub trait Sink: Sync {
    /// Stores `bytes` as the file `name` (no folders in the name).
    fn write(&self, name: &str, bytes: &[u8]) -> io::Result<()>;

    /// Stores a finished sub-output: the folder `name` holding `files` (the study writes
    /// each kind's design into a folder of its own, complete or not at all).
    fn write_folder(&self, name: &str, files: &MemorySink) -> io::Result<()>;
}

/// Files held in memory, by name, in name order.
#[derive(Debug, Default)]
pub struct MemorySink {
    files: Mutex<BTreeMap<String, Vec<u8>>>,
    folders: Mutex<BTreeMap<String, MemorySink>>,
}

impl MemorySink {
    /// No files yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// The files written, by name (a poisoned lock, a writer that panicked, gives what it
    /// holds).
    pub fn files(&self) -> BTreeMap<String, Vec<u8>> {
        self.files.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// The names of the sub-outputs written with [`Sink::write_folder`].
    pub fn folder_names(&self) -> Vec<String> {
        self.folders
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .keys()
            .cloned()
            .collect()
    }

    /// The files of the sub-output `name`, if written.
    pub fn folder_files(&self, name: &str) -> Option<BTreeMap<String, Vec<u8>>> {
        self.folders
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .get(name)
            .map(MemorySink::files)
    }
}

impl Sink for MemorySink {
    fn write(&self, name: &str, bytes: &[u8]) -> io::Result<()> {
        self.files
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .insert(name.to_string(), bytes.to_vec());
        Ok(())
    }

    fn write_folder(&self, name: &str, files: &MemorySink) -> io::Result<()> {
        let copy = MemorySink {
            files: Mutex::new(files.files()),
            folders: Mutex::new(BTreeMap::new()),
        };
        self.folders
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .insert(name.to_string(), copy);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_and_folders_are_kept_by_name() {
        let sink = MemorySink::new();
        sink.write("b.txt", b"2").unwrap();
        sink.write("a.txt", b"1").unwrap();
        let kind = MemorySink::new();
        kind.write("report.json", b"{}").unwrap();
        sink.write_folder("four-bar", &kind).unwrap();
        assert_eq!(sink.files().keys().collect::<Vec<_>>(), ["a.txt", "b.txt"]);
        assert_eq!(sink.folder_names(), ["four-bar"]);
        assert_eq!(sink.folder_files("four-bar").unwrap()["report.json"], b"{}");
    }
}
