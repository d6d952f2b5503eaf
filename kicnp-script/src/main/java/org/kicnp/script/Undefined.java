package org.kicnp.script;

/**
 * The Java value of JavaScript {@code undefined} and {@code null}. Script results never contain a Java
 * {@code null}: a statement script such as {@code Sendmsg(...)} whose host function returns nothing yields
 * {@link #INSTANCE}, and so do {@code null}/{@code undefined} elements of returned arrays and objects.
 */
public enum Undefined {
    INSTANCE;

    @Override public String toString() {
        return "undefined";
    }
}
