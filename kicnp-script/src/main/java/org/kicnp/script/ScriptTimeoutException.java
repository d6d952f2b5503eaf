package org.kicnp.script;

/**
 * A script was stopped because it ran too long: past the wall-clock limit or past the statement limit of its
 * {@link ScriptConfig}. The runtime stays usable; the context that ran the script is replaced.
 */
public final class ScriptTimeoutException extends ScriptException {

    /** Which of the two bounds a script exceeded. */
    public enum Limit { TIME, STATEMENTS }

    private final Limit limit;

    public ScriptTimeoutException(ScriptId id, Limit limit, String bound, Throwable cause) {
        super(id, id.describe() + " was stopped: it exceeded its " + (limit == Limit.TIME ? "time" : "statement")
                + " limit of " + bound + ".", cause);
        this.limit = limit;
    }

    /** The bound that was exceeded. */
    public Limit limit() {
        return limit;
    }
}
