//! Headless Chromium driven over the DevTools protocol on a pipe
//! (`--remote-debugging-pipe`: commands in on fd 3, answers and events out
//! on fd 4, each a JSON message ended by a NUL byte). The pipes are FIFOs
//! the shell opens as fds 3 and 4 before it becomes Chromium, so the test
//! needs neither `unsafe` nor a websocket.

use super::Scratch;
use serde_json::{json, Value};
use std::fs::File;
use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{channel, Receiver};
use std::time::{Duration, Instant};

/// How long any one answer may take.
const TIMEOUT: Duration = Duration::from_secs(60);

pub struct Browser {
    child: Child,
    to_browser: File,
    from_browser: Receiver<Value>,
    next_id: u64,
    /// Events not yet taken, in order.
    pub events: Vec<Value>,
    /// The profile, the pipes and Chromium's stderr.
    dir: Scratch,
}

impl Browser {
    /// Starts Chromium with a fresh profile in a directory of its own.
    pub fn start(name: &str) -> Browser {
        let dir = super::scratch(&format!("chromium-{name}"));
        let (to, from) = (dir.join("to-browser"), dir.join("from-browser"));
        for fifo in [&to, &from] {
            let made = Command::new("mkfifo")
                .arg(fifo)
                .status()
                .expect("mkfifo runs");
            assert!(made.success(), "mkfifo {}", fifo.display());
        }
        let chromium = which_chromium();
        let script = format!(
            "exec '{chromium}' --headless --no-sandbox --disable-gpu --disable-background-networking \
             --disable-component-update --no-first-run --disable-sync --hide-scrollbars \
             --user-data-dir='{}' --remote-debugging-pipe about:blank 3<'{}' 4>'{}'",
            dir.join("profile").display(),
            to.display(),
            from.display()
        );
        let child = Command::new("sh")
            .arg("-c")
            .arg(script)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(File::create(dir.join("stderr.txt")).unwrap())
            .spawn()
            .expect("sh starts");
        // The shell opens fd 3 for reading first, then fd 4 for writing:
        // open the other ends in the same order, or both sides wait forever.
        let to_browser = File::options().write(true).open(&to).unwrap();
        let reader = BufReader::new(File::open(&from).unwrap());
        let (send, from_browser) = channel();
        std::thread::spawn(move || {
            for message in reader.split(0) {
                let Ok(bytes) = message else { break };
                let Ok(value) = serde_json::from_slice::<Value>(&bytes) else {
                    break;
                };
                if send.send(value).is_err() {
                    break;
                }
            }
        });
        Browser {
            child,
            to_browser,
            from_browser,
            next_id: 0,
            events: Vec::new(),
            dir,
        }
    }

    /// Sends a command (to a page's session when given) and returns its result.
    pub fn call(&mut self, session: Option<&str>, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        let mut message = json!({ "id": id, "method": method, "params": params });
        if let Some(session) = session {
            message["sessionId"] = json!(session);
        }
        let mut bytes = serde_json::to_vec(&message).unwrap();
        bytes.push(0);
        self.to_browser.write_all(&bytes).unwrap();
        let deadline = Instant::now() + TIMEOUT;
        loop {
            let message = self.receive(deadline, method);
            if message["id"] == json!(id) {
                assert!(message.get("error").is_none(), "{method}: {message}");
                return message["result"].clone();
            }
            self.events.push(message);
        }
    }

    /// Waits for an event of `method`, keeping the others.
    pub fn wait_for(&mut self, method: &str) -> Value {
        if let Some(i) = self
            .events
            .iter()
            .position(|e| e["method"] == json!(method))
        {
            return self.events.remove(i);
        }
        let deadline = Instant::now() + TIMEOUT;
        loop {
            let message = self.receive(deadline, method);
            if message["method"] == json!(method) {
                return message;
            }
            self.events.push(message);
        }
    }

    fn receive(&mut self, deadline: Instant, waiting_for: &str) -> Value {
        let left = deadline.saturating_duration_since(Instant::now());
        self.from_browser.recv_timeout(left).unwrap_or_else(|e| {
            let log = std::fs::read_to_string(self.dir.join("stderr.txt")).unwrap_or_default();
            panic!("no answer to {waiting_for} from Chromium ({e}); its stderr:\n{log}")
        })
    }

    /// A new page, attached: its session id.
    pub fn new_page(&mut self) -> String {
        let target = self.call(None, "Target.createTarget", json!({ "url": "about:blank" }));
        let attached = self.call(
            None,
            "Target.attachToTarget",
            json!({ "targetId": target["targetId"], "flatten": true }),
        );
        attached["sessionId"].as_str().unwrap().to_string()
    }

    /// The value of a JavaScript expression evaluated in the page (the
    /// test's script, not the page's: the datasheet has none).
    pub fn eval(&mut self, session: &str, expression: &str) -> Value {
        let result = self.call(
            Some(session),
            "Runtime.evaluate",
            json!({ "expression": expression, "returnByValue": true }),
        );
        assert!(
            result.get("exceptionDetails").is_none(),
            "{expression}: {result}"
        );
        result["result"]["value"].clone()
    }
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Debian's `chromium`; ./scripts/test.sh installs it.
fn which_chromium() -> String {
    let found = std::env::var_os("PATH")
        .into_iter()
        .flat_map(|path| std::env::split_paths(&path).collect::<Vec<_>>())
        .map(|dir| dir.join("chromium"))
        .find(|p| p.is_file());
    match found {
        Some(path) => path.display().to_string(),
        None => panic!("chromium is not installed: run ./scripts/test.sh, which installs it"),
    }
}

/// Standard base64, as DevTools sends screenshots and PDFs.
pub fn base64(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        b'/' => 63,
        _ => panic!("not base64: {c}"),
    };
    let digits: Vec<u8> = text.bytes().filter(|&c| c != b'=').map(value).collect();
    digits
        .chunks(4)
        .flat_map(|chunk| {
            let n =
                chunk.iter().fold(0u32, |n, &d| n << 6 | u32::from(d)) << (6 * (4 - chunk.len()));
            let bytes = n.to_be_bytes();
            bytes[1..chunk.len()].to_vec()
        })
        .collect()
}

pub fn file_url(path: &Path) -> String {
    format!("file://{}", path.canonicalize().unwrap().display())
}
