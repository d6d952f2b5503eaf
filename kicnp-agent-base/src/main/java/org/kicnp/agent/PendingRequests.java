package org.kicnp.agent;

import java.io.IOException;
import java.time.Duration;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.kicnp.protocol.FeedbackStage;
import org.kicnp.protocol.Message;

/**
 * What an {@link AgentBase} awaits from the server, by id: the answer to each request it sent, and the feedback of
 * each command it sent (its {@link CommandTicket}). It makes the request ids too, from one counter. A caller waits
 * here, the read loop completes here, and a lost connection fails everything here: the server answers on the
 * connection a request came on, so a new connection will never hear of it.
 *
 * <p>Kept apart from the agent's API and from its {@link Supervisor} (the connection's life), which meet only here:
 * the correlation of answers to requests is the one piece of state both sides touch.
 */
final class PendingRequests {
    private final Map<String, CompletableFuture<Message>> pending = new ConcurrentHashMap<>();
    private final Map<String, CommandTicket> tickets = new ConcurrentHashMap<>();
    private final AtomicLong ids = new AtomicLong();
    private final Duration timeout;

    /** @param timeout how long {@link #request} waits for an answer */
    PendingRequests(Duration timeout) {
        this.timeout = timeout;
    }

    /** A fresh id for a request (and the tail of a command's id). */
    String nextId() {
        return Long.toString(ids.incrementAndGet());
    }

    /**
     * Sends a request through {@code send} and waits for its answer.
     *
     * @throws RequestRefusedException when the server answers with an error
     * @throws AgentTimeoutException when it does not answer within the request timeout
     * @throws NotConnectedException when the agent is not connected, or loses its connection before the answer
     */
    Message request(Message.Request r, Consumer<Message> send) {
        CompletableFuture<Message> answer = new CompletableFuture<>();
        pending.put(r.id(), answer);
        try {
            sendOrHearWhy(r, send, answer);
            Message m = answer.get(timeout.toMillis(), TimeUnit.MILLISECONDS);
            if (m instanceof Message.ErrorReply e) {
                throw new RequestRefusedException(e.code(), e.message());
            }
            return m;
        } catch (TimeoutException e) {
            throw new AgentTimeoutException("The server did not answer " + r.getClass().getSimpleName() + " '" + r.id()
                    + "' within " + AgentBase.words(timeout) + ".");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AgentException("Interrupted while waiting for the answer to '" + r.id() + "'.", e);
        } catch (ExecutionException e) {
            throw e.getCause() instanceof AgentException a ? a : new AgentException(e.getCause().getMessage(), e);
        } finally {
            pending.remove(r.id());
        }
    }

    /**
     * Sends {@code r}. When the connection fails under the write, what the server said is a better answer than the
     * closed socket: a request longer than the server's frame limit is refused as soon as its length is read, and the
     * server closes after saying so, often before the rest is written; the read loop then hears the refusal, closes
     * the socket the write is using, and fails every pending request with the server's reason. So a failed write
     * waits (within the request timeout) for that, and throws its own failure only when nothing comes.
     */
    private void sendOrHearWhy(Message.Request r, Consumer<Message> send, CompletableFuture<Message> answer)
            throws InterruptedException, ExecutionException {
        try {
            send.accept(r);
        } catch (NotConnectedException e) {
            if (!(e.getCause() instanceof IOException)) {
                throw e; // not connected at all: nobody will answer
            }
            try {
                answer.get(timeout.toMillis(), TimeUnit.MILLISECONDS); // the caller reads the outcome from it
            } catch (TimeoutException nothingCame) {
                throw e;
            }
        }
    }

    /** The answer to request {@code id}, to be completed by the read loop; for a request nobody waits on. */
    CompletableFuture<Message> expect(String id) {
        CompletableFuture<Message> answer = new CompletableFuture<>();
        pending.put(id, answer);
        return answer;
    }

    /** The server answered request {@code id}; an answer nobody waits for any more is dropped. */
    void complete(String id, Message answer) {
        CompletableFuture<Message> f = pending.remove(id);
        if (f != null) {
            f.complete(answer);
        }
    }

    /** Fails every request waiting for an answer, each with a fresh exception. */
    void failAll(Supplier<AgentException> failure) {
        pending.forEach((id, f) -> f.completeExceptionally(failure.get()));
        pending.clear();
    }

    /** Follows a command about to be sent: its feedback goes to {@code ticket}. */
    void track(CommandTicket ticket) {
        tickets.put(ticket.command().id(), ticket);
    }

    /** Stops following a command the server did not take. */
    void untrack(String commandId) {
        tickets.remove(commandId);
    }

    /** Feedback on a command this agent sent; the last one ends the following. */
    void feedback(Message.Feedback f) {
        CommandTicket t = f.stage().terminal() ? tickets.remove(f.id()) : tickets.get(f.id());
        if (t != null) {
            t.received(f);
        }
    }

    /** The connection is lost: the server sends feedback to the connection that issued a command, so each fails. */
    void commandsLost() {
        tickets.forEach((id, t) -> t.received(new Message.Feedback(id, t.command().robot(), FeedbackStage.FAILED,
                Optional.empty(), "the connection to the gateway was lost before command '" + id + "' ended")));
        tickets.clear();
    }
}
