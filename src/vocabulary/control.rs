//! How commands travel: a script or the page sends one through a [`ControlHandle`]; the
//! plant's thread takes it at the start of its next block ([`CommandInbox`]), stamps it
//! with that block's virtual time and carries it on the frame to its target, which
//! carries it out before that frame's samples and answers. Accepted commands make the
//! session's log.

use std::collections::VecDeque;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::Duration;

use crossbeam_channel::{Receiver, Sender, TrySendError, bounded, unbounded};

use super::command::{Reply, RigCommand, Target, TimedCommand};
use super::refusal::Refusal;

/// How long a sender waits for the answer (s of wall time).
const ANSWER_WAIT_S: f64 = 10.0;

/// Most commands waiting for the plant's thread; more are refused at once as busy (the
/// plant takes them at every block, so only a flood fills the queue).
pub const MAX_QUEUED_COMMANDS: usize = 256;

/// An answer: the order the plant's thread took the command in, and the reply.
pub type Answer = (u64, Reply);

/// The session's log: each accepted live command with the order the plant's thread took
/// it in, and where each is also written the moment it takes effect.
type SessionLog = Arc<Mutex<LogState>>;

/// Where each accepted command is also written as it takes effect.
type Journal = Box<dyn FnMut(&TimedCommand) + Send>;

/// What the session's log holds.
#[derive(Default)]
struct LogState {
    entries: Vec<(u64, TimedCommand)>,
    journal: Option<Journal>,
}

impl std::fmt::Debug for LogState {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LogState")
            .field("entries", &self.entries)
            .field("journal", &self.journal.is_some())
            .finish()
    }
}

/// A command on its way to its target.
#[derive(Clone, Debug)]
pub struct Pending {
    /// The command.
    pub command: RigCommand,
    /// Virtual time it takes effect at (s).
    pub at_s: f64,
    /// The order the plant's thread took it in.
    pub order: u64,
    answer: Option<Sender<Answer>>,
    log: Option<SessionLog>,
}

impl Pending {
    /// Answers the sender (if one waits): carried out, or refused with why. A live
    /// command carried out joins the session's log here, as it takes effect, whether or
    /// not its sender still waits.
    pub fn answer(&self, outcome: Result<(), Refusal>) {
        if let (Ok(()), Some(log)) = (&outcome, &self.log) {
            let timed = TimedCommand {
                at_s: self.at_s,
                command: self.command.clone(),
            };
            let mut log = log.lock().unwrap_or_else(PoisonError::into_inner);
            if let Some(journal) = &mut log.journal {
                journal(&timed);
            }
            log.entries.push((self.order, timed));
        }
        if let Some(tx) = &self.answer {
            let reply = Reply {
                ok: outcome.is_ok(),
                at_s: self.at_s,
                error: outcome.err().map(|refusal| refusal.to_string()),
            };
            // The sender may have given up waiting; nothing else to do then.
            let _ = tx.send((self.order, reply));
        }
    }
}

/// A command as sent, before the plant's thread takes it.
#[derive(Debug)]
pub struct Request {
    command: RigCommand,
    answer: Sender<Answer>,
    log: SessionLog,
}

/// Where scripts and pages send commands; clones share the session's log.
#[derive(Clone, Debug)]
pub struct ControlHandle {
    requests: Sender<Request>,
    log: SessionLog,
    wait: Duration,
    busy: Arc<AtomicU64>,
}

impl ControlHandle {
    /// A handle and the receiving end the run's plant thread reads.
    pub fn new() -> (Self, Receiver<Request>) {
        let (requests, inbox) = bounded(MAX_QUEUED_COMMANDS);
        let handle = Self {
            requests,
            log: Arc::default(),
            wait: Duration::from_secs_f64(ANSWER_WAIT_S),
            busy: Arc::default(),
        };
        (handle, inbox)
    }

    /// The same handle waiting at most `wait` for each answer.
    pub fn waiting(self, wait: Duration) -> Self {
        Self { wait, ..self }
    }

    /// Sends `command` and waits for its answer. The command joins the session's log
    /// when it is carried out (see [`Pending::answer`]), even after the wait has ended.
    pub fn send(&self, command: RigCommand) -> Reply {
        let (answer, answers) = bounded(1);
        let request = Request {
            command,
            answer,
            log: Arc::clone(&self.log),
        };
        match self.requests.try_send(request) {
            Ok(()) => {}
            Err(TrySendError::Full(_)) => {
                self.busy.fetch_add(1, Ordering::Relaxed);
                return refused(&format!(
                    "the rig is busy: {MAX_QUEUED_COMMANDS} commands wait for it; send again"
                ));
            }
            Err(TrySendError::Disconnected(_)) => return refused("the run has ended"),
        }
        match answers.recv_timeout(self.wait) {
            Ok((_, reply)) => reply,
            Err(_) => refused(
                "no answer from the rig yet (it has ended, or its queues are full); if it is carried out later it still joins the session",
            ),
        }
    }

    /// Writes each accepted command with `journal` too, the moment it takes effect (the
    /// panel appends it to `session.toml`, so that a killed session loses none).
    pub fn journal_to(&self, journal: impl FnMut(&TimedCommand) + Send + 'static) {
        self.log
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .journal = Some(Box::new(journal));
    }

    /// Commands refused so far because the queue was full.
    pub fn refused_busy(&self) -> u64 {
        self.busy.load(Ordering::Relaxed)
    }

    /// The accepted commands in the order they took effect.
    pub fn session(&self) -> Vec<TimedCommand> {
        let mut log = self
            .log
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .entries
            .clone();
        log.sort_by_key(|(order, _)| *order);
        log.into_iter().map(|(_, c)| c).collect()
    }
}

fn refused(why: &str) -> Reply {
    Reply {
        ok: false,
        at_s: f64::NAN,
        error: Some(why.to_string()),
    }
}

/// What the plant's thread takes commands from: a scenario's timed commands and, live,
/// the requests of scripts and pages.
#[derive(Debug)]
pub struct CommandInbox {
    scheduled: VecDeque<(u64, RigCommand)>,
    scheduled_answers: (Sender<Answer>, Receiver<Answer>),
    live: Option<Receiver<Request>>,
    targets: Vec<Target>,
    next_order: u64,
}

impl CommandInbox {
    /// An inbox for a run at `rate_hz` whose parts are `targets`: the scenario's
    /// `scheduled` commands (each at the first block starting at or after its time) and
    /// the `live` requests.
    pub fn new(
        scheduled: &[TimedCommand],
        live: Option<Receiver<Request>>,
        targets: Vec<Target>,
        rate_hz: f64,
    ) -> Self {
        let mut scheduled: Vec<(u64, RigCommand)> = scheduled
            .iter()
            .map(|c| ((c.at_s * rate_hz).round() as u64, c.command.clone()))
            .collect();
        scheduled.sort_by_key(|(at, _)| *at);
        Self {
            scheduled: scheduled.into(),
            scheduled_answers: unbounded(),
            live,
            targets,
            next_order: 0,
        }
    }

    /// The commands that take effect at the block starting at sample `start_sample`
    /// (virtual time `at_s`): the scheduled ones due, then the live ones waiting. One
    /// whose target this run lacks is refused at once.
    pub fn due(&mut self, start_sample: u64, at_s: f64) -> Vec<Pending> {
        let mut due = Vec::new();
        while self
            .scheduled
            .front()
            .is_some_and(|(at, _)| *at <= start_sample)
        {
            if let Some((_, command)) = self.scheduled.pop_front() {
                due.push((command, Some(self.scheduled_answers.0.clone()), None));
            }
        }
        if let Some(live) = &self.live {
            due.extend(
                live.try_iter()
                    .map(|r| (r.command, Some(r.answer), Some(r.log))),
            );
        }
        let mut pending = Vec::with_capacity(due.len());
        for (command, answer, log) in due {
            let p = Pending {
                command,
                at_s,
                order: self.next_order,
                answer,
                log,
            };
            self.next_order += 1;
            if self.targets.contains(&p.command.target()) {
                pending.push(p);
            } else {
                p.answer(Err(Refusal::NotFor(format!(
                    "this run has no {:?} to carry out `{}`",
                    p.command.target(),
                    command_name(&p.command)
                ))));
            }
        }
        pending
    }
}

impl CommandInbox {
    /// Whether scripts and pages can send commands (a live run).
    pub fn is_live(&self) -> bool {
        self.live.is_some()
    }

    /// Where the answers to the scenario's own commands arrive (read it after the run:
    /// the refused ones are the run's warnings).
    pub fn scheduled_answers(&self) -> Receiver<Answer> {
        self.scheduled_answers.1.clone()
    }
}

/// The scenario's commands that were refused, as warnings, from their answers.
pub fn refusals(answers: &Receiver<Answer>) -> Vec<String> {
    let mut refused: Vec<Answer> = answers.try_iter().filter(|(_, r)| !r.ok).collect();
    refused.sort_by_key(|(order, _)| *order);
    refused
        .into_iter()
        .map(|(_, r)| {
            format!(
                "a [[command]] at t = {} s was refused: {}",
                r.at_s,
                r.error.unwrap_or_default()
            )
        })
        .collect()
}

/// The command's `cmd` name.
pub fn command_name(command: &RigCommand) -> String {
    serde_json::to_value(command)
        .ok()
        .and_then(|v| v.get("cmd").and_then(|c| c.as_str()).map(str::to_string))
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 23, item 4: a command answered "no answer" after its sender's wait still
    /// took effect but was left out of the session, so the replay differed. It joins the
    /// session when it is carried out; a refused one never does.
    #[test]
    fn a_command_carried_out_after_its_sender_gave_up_still_joins_the_session() {
        let (handle, requests) = ControlHandle::new();
        let handle = handle.waiting(Duration::from_millis(20));
        let mut inbox = CommandInbox::new(&[], Some(requests), vec![Target::Plant], 51_200.0);
        let late = RigCommand::SetSpeed { rpm: 1300.0 };
        let refused_one = RigCommand::SetSpeed { rpm: -5.0 };
        for command in [late.clone(), refused_one] {
            let reply = handle.send(command);
            assert!(!reply.ok, "nobody answered within the wait");
        }
        assert!(handle.session().is_empty(), "nothing carried out yet");
        let pending = inbox.due(76_800, 1.5);
        assert_eq!(pending.len(), 2);
        pending[0].answer(Ok(()));
        pending[1].answer(Err(Refusal::Setting("speed -5: below 0".into())));
        assert_eq!(
            handle.session(),
            vec![TimedCommand {
                at_s: 1.5,
                command: late
            }]
        );
    }

    /// Issue 23, item 5: a command flood grew the memory without bound. At most
    /// [`MAX_QUEUED_COMMANDS`] wait; the rest are refused at once as busy and counted.
    #[test]
    fn a_flood_of_commands_fills_a_bounded_queue_and_the_rest_are_refused_as_busy() {
        let (handle, requests) = ControlHandle::new();
        let handle = handle.waiting(Duration::ZERO);
        let extra = 44;
        let replies: Vec<Reply> = (0..MAX_QUEUED_COMMANDS + extra)
            .map(|_| handle.send(RigCommand::SetSpeed { rpm: 600.0 }))
            .collect();
        assert_eq!(requests.len(), MAX_QUEUED_COMMANDS);
        assert_eq!(handle.refused_busy(), extra as u64);
        let busy = replies
            .iter()
            .filter(|r| r.error.as_deref().is_some_and(|e| e.contains("busy")))
            .count();
        assert_eq!(busy, extra);
    }
}
