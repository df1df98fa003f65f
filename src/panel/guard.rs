//! What the panel trusts (see `docs/security.md`). On loopback: requests whose Host is
//! this server by address or a localhost name (a rebound DNS name is refused), and, for
//! commands and the stream, an Origin of such a host when a browser sends one (another
//! site's page is refused). Bound beyond loopback: besides, every API request carries
//! the session's token, generated at start and printed in the panel's URL. Commands must
//! be JSON (`Content-Type: application/json`), which a page of another origin cannot send
//! without the browser asking first.

use std::io::Read;
use std::net::SocketAddr;

use super::http::HttpRequest;

/// Why a request is refused: its HTTP status and the reason.
pub type Refused = (u16, String);

/// The checks of one server.
#[derive(Clone, Debug)]
pub struct Guard {
    address: SocketAddr,
    token: Option<String>,
}

impl Guard {
    /// The guard of a server bound to `address`: with a fresh token unless it is loopback.
    pub fn new(address: SocketAddr) -> std::io::Result<Self> {
        let token = if address.ip().is_loopback() {
            None
        } else {
            Some(fresh_token()?)
        };
        Ok(Self { address, token })
    }

    /// The token API requests must carry (`None` on loopback).
    pub fn token(&self) -> Option<&str> {
        self.token.as_deref()
    }

    /// Checks `request` for `path`: its Host, its Origin where it changes the rig or
    /// opens the stream, its token for the API, and JSON for a command.
    pub fn check(&self, request: &HttpRequest, path: &str) -> Result<(), Refused> {
        let host = request.header("Host").unwrap_or_default();
        if self.token.is_none() && !self.is_local_host(host) {
            return Err((403, format!("Host `{host}` is not this panel's address")));
        }
        let api = path.starts_with("/api/");
        let acts = path == "/api/command" || path == "/api/stream";
        if acts && let Some(origin) = request.header("Origin") {
            let origin_host = origin.split("://").nth(1).unwrap_or("");
            let same = if self.token.is_none() {
                self.is_local_host(origin_host)
            } else {
                origin_host == host
            };
            if !same {
                return Err((403, format!("Origin `{origin}` is not this panel")));
            }
        }
        if api && let Some(token) = &self.token {
            let given = query_value(&request.target, "token")
                .or_else(|| request.header("X-Testrig-Token").map(str::to_string));
            if given.as_deref() != Some(token.as_str()) {
                return Err((
                    401,
                    "the panel's token is missing or wrong: use the URL it printed".into(),
                ));
            }
        }
        if path == "/api/command" && request.method == "POST" {
            let json = request.header("Content-Type").is_some_and(|t| {
                t.split(';')
                    .next()
                    .is_some_and(|m| m.trim() == "application/json")
            });
            if !json {
                return Err((
                    415,
                    "a command is JSON: Content-Type: application/json".into(),
                ));
            }
        }
        Ok(())
    }

    /// Whether `host` (`name:port`) names this server on loopback.
    fn is_local_host(&self, host: &str) -> bool {
        let port = self.address.port();
        host == self.address.to_string()
            || [
                format!("localhost:{port}"),
                format!("127.0.0.1:{port}"),
                format!("[::1]:{port}"),
            ]
            .iter()
            .any(|h| h == host)
    }
}

/// The value of `key` in `url`'s query.
fn query_value(url: &str, key: &str) -> Option<String> {
    let query = url.split_once('?')?.1;
    query.split('&').find_map(|pair| {
        let (k, v) = pair.split_once('=')?;
        (k == key).then(|| v.to_string())
    })
}

/// 128 bits from the system's random source, as hex: a secret, so not a seeded stream.
fn fresh_token() -> std::io::Result<String> {
    let mut bytes = [0u8; 16];
    std::fs::File::open("/dev/urandom")?.read_exact(&mut bytes)?;
    Ok(bytes.iter().map(|b| format!("{b:02x}")).collect())
}
