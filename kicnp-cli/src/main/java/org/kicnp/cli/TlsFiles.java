package org.kicnp.cli;

import io.netty.handler.ssl.SslContext;
import io.netty.handler.ssl.SslContextBuilder;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.cert.Certificate;
import java.security.cert.CertificateException;
import java.security.cert.CertificateFactory;
import java.util.Collection;
import java.util.Collections;
import java.util.Optional;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;

/**
 * The TLS files of the command line, read with the JDK alone: the server's key and certificate as a keystore made by
 * {@code keytool} (PKCS12 or JKS) with its password in a file, and what an agent trusts — the server's certificate
 * (PEM or DER, as {@code keytool -exportcert} writes it) or a keystore holding it. Every problem is an
 * {@link IllegalArgumentException} naming the file and what is wrong with it.
 */
final class TlsFiles {
    private TlsFiles() {
    }

    /** The server side of TLS from a keystore with one private key and its certificate chain. */
    static SslContext server(Path keystore, Path passwordFile) {
        char[] password = password(passwordFile);
        KeyStore ks = keyStore(keystore, password, "--tls-keystore");
        try {
            if (Collections.list(ks.aliases()).stream().noneMatch(a -> isKey(ks, a))) {
                throw new IllegalArgumentException("The keystore '" + keystore + "' (--tls-keystore) holds no private "
                        + "key; make one with keytool -genkeypair (see docs/deployment.md).");
            }
            KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
            kmf.init(ks, password);
            return SslContextBuilder.forServer(kmf).build();
        } catch (GeneralSecurityException | IOException e) {
            throw new IllegalArgumentException("The keystore '" + keystore + "' (--tls-keystore) cannot serve TLS: "
                    + e.getMessage(), e);
        }
    }

    /**
     * The client side of TLS that trusts exactly what {@code trust} holds: a certificate (PEM or DER), or a keystore
     * (then {@code passwordFile} gives its password, if it has one).
     */
    static SSLContext client(Path trust, Optional<Path> passwordFile) {
        KeyStore ts;
        Optional<Collection<? extends Certificate>> certs = certificates(trust);
        try {
            if (certs.isPresent()) {
                ts = KeyStore.getInstance(KeyStore.getDefaultType());
                ts.load(null, null);
                int i = 0;
                for (Certificate c : certs.get()) {
                    ts.setCertificateEntry("trusted-" + i++, c);
                }
            } else {
                ts = keyStore(trust, passwordFile.map(TlsFiles::password).orElse(new char[0]), "--tls-trust");
            }
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(ts);
            SSLContext ctx = SSLContext.getInstance("TLS");
            ctx.init(null, tmf.getTrustManagers(), null);
            return ctx;
        } catch (GeneralSecurityException | IOException e) {
            throw new IllegalArgumentException("The file '" + trust + "' (--tls-trust) cannot be trusted for TLS: "
                    + e.getMessage(), e);
        }
    }

    /** The certificates of a PEM or DER file; empty when the file is not one (a keystore, say). */
    private static Optional<Collection<? extends Certificate>> certificates(Path file) {
        try (InputStream in = Files.newInputStream(file)) {
            Collection<? extends Certificate> certs = CertificateFactory.getInstance("X.509").generateCertificates(in);
            return certs.isEmpty() ? Optional.empty() : Optional.of(certs);
        } catch (CertificateException e) {
            return Optional.empty();
        } catch (IOException e) {
            throw new IllegalArgumentException("The file '" + file + "' (--tls-trust) cannot be read: "
                    + e.getMessage(), e);
        }
    }

    private static KeyStore keyStore(Path file, char[] password, String option) {
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("There is no keystore '" + file + "' (" + option + ").");
        }
        try {
            return KeyStore.getInstance(file.toFile(), password);
        } catch (IOException e) {
            // A wrong password and a damaged file both surface here; the JDK's message says which.
            throw new IllegalArgumentException("The keystore '" + file + "' (" + option + ") cannot be opened: "
                    + e.getMessage() + " (a wrong password, or not a PKCS12 or JKS keystore).", e);
        } catch (GeneralSecurityException e) {
            throw new IllegalArgumentException("The keystore '" + file + "' (" + option + ") cannot be opened: "
                    + e.getMessage(), e);
        }
    }

    private static boolean isKey(KeyStore ks, String alias) {
        try {
            return ks.isKeyEntry(alias);
        } catch (GeneralSecurityException e) {
            return false;
        }
    }

    /** The first line of a password file. */
    static char[] password(Path file) {
        try {
            String text = Files.readString(file, StandardCharsets.UTF_8);
            int end = text.indexOf('\n');
            String line = end < 0 ? text : text.substring(0, end);
            return line.strip().toCharArray();
        } catch (IOException e) {
            throw new IllegalArgumentException("The password file '" + file + "' (--tls-password-file) cannot be "
                    + "read: " + e.getMessage(), e);
        }
    }
}
