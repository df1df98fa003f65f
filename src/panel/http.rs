//! The panel's HTTP/1.1, bounded everywhere a client could make it grow or wait: a
//! request's head is read up to [`MAX_HEAD_BYTES`] and [`MAX_HEADERS`] lines, its body up
//! to [`MAX_BODY_BYTES`] with a `Content-Length`, the whole request within
//! [`REQUEST_DEADLINE`]; one request a connection (`Connection: close`). The head is
//! parsed by `httparse`.

use std::io::{ErrorKind, Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};

/// Largest request head (request line and headers) read (bytes).
pub const MAX_HEAD_BYTES: usize = 16 * 1024;
/// Most header lines a request may carry.
pub const MAX_HEADERS: usize = 64;
/// Largest request body read (bytes): a command is well under 1 kB.
pub const MAX_BODY_BYTES: usize = 64 * 1024;
/// Time a client has to send its whole request, from the connection's acceptance.
pub const REQUEST_DEADLINE: Duration = Duration::from_secs(5);

/// One request, read whole.
#[derive(Clone, Debug)]
pub struct HttpRequest {
    /// The method (`GET`, `POST`, …).
    pub method: String,
    /// The request target: the path and its query.
    pub target: String,
    /// The header lines as (name, value), in the order sent.
    pub headers: Vec<(String, String)>,
    /// The body (`Content-Length` bytes).
    pub body: Vec<u8>,
}

impl HttpRequest {
    /// The value of header `name` (case-insensitive), if sent.
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|(_, v)| v.as_str())
    }

    /// The target's path, without its query.
    pub fn path(&self) -> &str {
        self.target.split('?').next().unwrap_or("")
    }
}

/// Why no request was read.
#[derive(Debug, thiserror::Error)]
pub enum RequestError {
    /// The client closed the connection before sending anything.
    #[error("the connection closed before a request")]
    Closed,
    /// The request was not complete within `REQUEST_DEADLINE`.
    #[error("no complete request within {} s", REQUEST_DEADLINE.as_secs())]
    TimedOut,
    /// The head is longer than [`MAX_HEAD_BYTES`] or has more than `MAX_HEADERS` lines.
    #[error("the request head is over {MAX_HEAD_BYTES} bytes or {MAX_HEADERS} lines")]
    HeadTooLarge,
    /// The body is longer than [`MAX_BODY_BYTES`].
    #[error("the body is over {MAX_BODY_BYTES} bytes")]
    BodyTooLarge,
    /// A body sent without a `Content-Length` (chunked).
    #[error("a body needs a Content-Length")]
    LengthRequired,
    /// Not HTTP/1.x.
    #[error("not an HTTP/1.1 request: {0}")]
    Malformed(String),
    /// The connection failed.
    #[error("reading the request: {0}")]
    Io(std::io::Error),
}

impl RequestError {
    /// The status to answer with, where the client is still there to read it.
    pub fn status(&self) -> Option<u16> {
        match self {
            Self::Closed | Self::Io(_) => None,
            Self::TimedOut => Some(408),
            Self::HeadTooLarge => Some(431),
            Self::BodyTooLarge => Some(413),
            Self::LengthRequired => Some(411),
            Self::Malformed(_) => Some(400),
        }
    }
}

/// Reads one request from `conn` within [`REQUEST_DEADLINE`] of now.
pub fn read_request(conn: &mut TcpStream) -> Result<HttpRequest, RequestError> {
    let deadline = Instant::now() + REQUEST_DEADLINE;
    read_request_from(conn, |c: &mut TcpStream| {
        let left = deadline
            .checked_duration_since(Instant::now())
            .filter(|d| !d.is_zero())
            .ok_or(RequestError::TimedOut)?;
        c.set_read_timeout(Some(left)).map_err(RequestError::Io)
    })
}

/// Reads one request from `reader`, calling `before_read` before every read (where a
/// socket sets its remaining time).
pub fn read_request_from<R: Read>(
    reader: &mut R,
    mut before_read: impl FnMut(&mut R) -> Result<(), RequestError>,
) -> Result<HttpRequest, RequestError> {
    let mut buffer = Vec::with_capacity(1024);
    let mut chunk = [0u8; 4096];
    let (mut request, head_len) = loop {
        before_read(reader)?;
        let n = read_some(reader, &mut chunk)?;
        if n == 0 {
            return Err(if buffer.is_empty() {
                RequestError::Closed
            } else {
                RequestError::Malformed("the connection closed inside the head".into())
            });
        }
        buffer.extend_from_slice(&chunk[..n]);
        if let Some(parsed) = parse_head(&buffer)? {
            break parsed;
        }
        if buffer.len() > MAX_HEAD_BYTES {
            return Err(RequestError::HeadTooLarge);
        }
    };
    let length = body_length(&request)?;
    request.body = buffer.split_off(head_len);
    if request.body.len() > length {
        request.body.truncate(length);
    }
    while request.body.len() < length {
        before_read(reader)?;
        let want = (length - request.body.len()).min(chunk.len());
        let n = read_some(reader, &mut chunk[..want])?;
        if n == 0 {
            return Err(RequestError::Malformed(
                "the connection closed inside the body".into(),
            ));
        }
        request.body.extend_from_slice(&chunk[..n]);
    }
    Ok(request)
}

/// One read, a timeout turned into [`RequestError::TimedOut`].
fn read_some(reader: &mut impl Read, into: &mut [u8]) -> Result<usize, RequestError> {
    loop {
        return match reader.read(into) {
            Ok(n) => Ok(n),
            Err(e) if e.kind() == ErrorKind::Interrupted => continue,
            Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => {
                Err(RequestError::TimedOut)
            }
            Err(e) => Err(RequestError::Io(e)),
        };
    }
}

/// The request head at the start of `bytes` and its length, once complete (`None`: more
/// bytes needed). The body is left empty.
pub fn parse_head(bytes: &[u8]) -> Result<Option<(HttpRequest, usize)>, RequestError> {
    let mut headers = [httparse::EMPTY_HEADER; MAX_HEADERS];
    let mut head = httparse::Request::new(&mut headers);
    let length = match head.parse(bytes) {
        Ok(httparse::Status::Complete(length)) => length,
        Ok(httparse::Status::Partial) => return Ok(None),
        Err(httparse::Error::TooManyHeaders) => return Err(RequestError::HeadTooLarge),
        Err(e) => return Err(RequestError::Malformed(e.to_string())),
    };
    if length > MAX_HEAD_BYTES {
        return Err(RequestError::HeadTooLarge);
    }
    let request = HttpRequest {
        method: head.method.unwrap_or_default().to_string(),
        target: head.path.unwrap_or_default().to_string(),
        headers: head
            .headers
            .iter()
            .map(|h| {
                (
                    h.name.to_string(),
                    String::from_utf8_lossy(h.value).into_owned(),
                )
            })
            .collect(),
        body: Vec::new(),
    };
    Ok(Some((request, length)))
}

/// The body's length from `Content-Length` (0 without one); a chunked body is refused.
fn body_length(request: &HttpRequest) -> Result<usize, RequestError> {
    if request.header("Transfer-Encoding").is_some() {
        return Err(RequestError::LengthRequired);
    }
    let Some(text) = request.header("Content-Length") else {
        return Ok(0);
    };
    let length: usize = text
        .trim()
        .parse()
        .map_err(|_| RequestError::Malformed(format!("Content-Length `{text}`")))?;
    if length > MAX_BODY_BYTES {
        return Err(RequestError::BodyTooLarge);
    }
    Ok(length)
}

/// One response, written whole with `Content-Length` and `Connection: close`.
#[derive(Clone, Debug)]
pub struct HttpResponse {
    /// The status code.
    pub status: u16,
    /// Header lines besides `Content-Length` and `Connection`.
    pub headers: Vec<(&'static str, String)>,
    /// The body.
    pub body: Vec<u8>,
}

impl HttpResponse {
    /// A response of `status` with `body` of `content_type`.
    pub fn new(status: u16, content_type: &str, body: impl Into<Vec<u8>>) -> Self {
        Self {
            status,
            headers: vec![("Content-Type", content_type.to_string())],
            body: body.into(),
        }
    }

    /// The same with header `name: value` added.
    pub fn with_header(mut self, name: &'static str, value: &str) -> Self {
        self.headers.push((name, value.to_string()));
        self
    }

    /// Writes the response to `out`.
    pub fn write_to(&self, out: &mut impl Write) -> std::io::Result<()> {
        let mut head = format!("HTTP/1.1 {} {}\r\n", self.status, reason(self.status));
        for (name, value) in &self.headers {
            head.push_str(&format!("{name}: {value}\r\n"));
        }
        head.push_str(&format!(
            "Content-Length: {}\r\nConnection: close\r\n\r\n",
            self.body.len()
        ));
        out.write_all(head.as_bytes())?;
        out.write_all(&self.body)?;
        out.flush()
    }
}

/// The reason phrase of the statuses the panel sends.
fn reason(status: u16) -> &'static str {
    match status {
        101 => "Switching Protocols",
        200 => "OK",
        400 => "Bad Request",
        401 => "Unauthorized",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        411 => "Length Required",
        413 => "Content Too Large",
        415 => "Unsupported Media Type",
        431 => "Request Header Fields Too Large",
        503 => "Service Unavailable",
        _ => "",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(bytes: &[u8]) -> Result<HttpRequest, RequestError> {
        read_request_from(&mut &bytes[..], |_| Ok(()))
    }

    #[test]
    fn a_request_is_read_with_its_headers_and_body() {
        let r = read(
            b"POST /api/command?x=1 HTTP/1.1\r\nHost: a\r\ncontent-length: 4\r\n\r\nbodyEXTRA",
        )
        .expect("read");
        assert_eq!(r.method, "POST");
        assert_eq!(r.path(), "/api/command");
        assert_eq!(r.header("Content-Length"), Some("4"));
        assert_eq!(r.body, b"body");
    }

    #[test]
    fn oversized_heads_and_bodies_are_refused_with_their_status() {
        let long = format!(
            "GET / HTTP/1.1\r\nX: {}\r\n\r\n",
            "a".repeat(MAX_HEAD_BYTES)
        );
        assert_eq!(read(long.as_bytes()).unwrap_err().status(), Some(431));
        let many: String = (0..=MAX_HEADERS).map(|k| format!("X{k}: 1\r\n")).collect();
        let many = format!("GET / HTTP/1.1\r\n{many}\r\n");
        assert_eq!(read(many.as_bytes()).unwrap_err().status(), Some(431));
        let body = format!(
            "POST / HTTP/1.1\r\nContent-Length: {}\r\n\r\n",
            MAX_BODY_BYTES + 1
        );
        assert_eq!(read(body.as_bytes()).unwrap_err().status(), Some(413));
        let chunked = b"POST / HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n";
        assert_eq!(read(chunked).unwrap_err().status(), Some(411));
        assert_eq!(read(b"\x16\x03\x01 hello").unwrap_err().status(), Some(400));
        assert!(matches!(read(b""), Err(RequestError::Closed)));
        let short = b"POST / HTTP/1.1\r\nContent-Length: 10\r\n\r\nabc";
        assert_eq!(read(short).unwrap_err().status(), Some(400));
    }
}
