package org.kicnp.cli;

import java.nio.file.Path;
import java.util.Optional;
import javax.net.SocketFactory;
import picocli.CommandLine.Option;
import picocli.CommandLine.ScopeType;

/**
 * The options of a verb that connects to a server's gateway over TLS ({@code serve --listen} with
 * {@code --tls-keystore}): what to trust. Without {@code --tls-trust} the connection is plain TCP, as to the
 * gateway's loopback port.
 */
final class TlsTrustOptions {
    @Option(names = "--tls-trust", paramLabel = "FILE", scope = ScopeType.INHERIT,
            description = "Connect over TLS, trusting the server's certificate in FILE (PEM or DER, as keytool "
                    + "-exportcert writes it) or a keystore holding it (with --tls-password-file). Needed for a "
                    + "server's --listen address; not for its loopback port.")
    Path trust;

    @Option(names = "--tls-password-file", paramLabel = "FILE", scope = ScopeType.INHERIT,
            description = "The password of the --tls-trust keystore: the file's first line.")
    Path passwordFile;

    /**
     * The socket factory of the connection: TLS trusting {@code --tls-trust}, or empty for plain TCP.
     *
     * @throws IllegalArgumentException naming the file and what is wrong with it
     */
    Optional<SocketFactory> socketFactory() {
        if (trust == null) {
            if (passwordFile != null) {
                throw new IllegalArgumentException("--tls-password-file is the password of --tls-trust, which was "
                        + "not given.");
            }
            return Optional.empty();
        }
        return Optional.of(TlsFiles.client(trust, Optional.ofNullable(passwordFile)).getSocketFactory());
    }
}
