package rp1.simulator.batch;

import java.io.ByteArrayInputStream;
import java.io.Closeable;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.MalformedURLException;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.net.URLConnection;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.WeakHashMap;
import java.util.concurrent.ConcurrentHashMap;

import rp1.rossum.RsClient;

/**
 * The class loader of one run's robot ({@code --isolation loader}): the robot's classes, and every
 * class of the class path that is not the simulator's or the client library's, are loaded afresh
 * for each run, so a static field of the robot starts anew in every run, as it would in a process
 * of its own. The library ({@code rp1.rossum}) and the simulator come from the sweep's loader: the
 * server and the robot must agree on {@code RsClient}. A class the run's loader cannot find on the
 * class path is the sweep loader's.
 *
 * <p>A resource the robot reads as a stream (its {@code rossum.ini}, next to its class) is not read
 * through the jar the whole JVM shares, as {@link URLClassLoader} reads it: that loader closes the
 * shared jar when it is closed, so one run ending pulled the jar from under another run reading it,
 * and the other run failed ({@code ZipFile closed}, or a {@code NullPointerException} inside
 * {@code JarURLConnection}) or its robot quietly went on without its settings. A resource in a jar is
 * read once per sweep, by a connection of its own, and each run gets the bytes; one in a folder is
 * opened for the stream alone, and closed with the loader if the run left it open.
 */
final class RunClassLoader extends URLClassLoader {
    static {
        registerAsParallelCapable();
    }

    private final Source source;
    /** The streams this loader opened and its robot may not have closed; closed with the loader. */
    private final Map<Closeable, Void> streams = new WeakHashMap<>();

    private RunClassLoader(Source source) {
        super("rp1-run", source.urls, source.parent);
        this.source = source;
    }

    /**
     * What the loaders of a sweep's runs have in common, worked out once for all of them: the folders
     * and jars they load from, and which class names are the sweep's to share. A run's robot resolves
     * dozens of the library's names; working out where each one comes from anew (its code source made
     * into a URL) was a twentieth of a warm sweep's processor time.
     */
    static final class Source {
        private final URL[] urls;
        private final Set<URL> shared;
        private final ClassLoader parent;
        private final Map<String, Boolean> sharedNames = new ConcurrentHashMap<>();
        /** The resources runs have read from jars, by URL: a jar does not change while a sweep runs. */
        private final Map<String, byte[]> jarResources = new ConcurrentHashMap<>();

        private Source(URL[] urls, Set<URL> shared, ClassLoader parent) {
            this.urls = urls;
            this.shared = shared;
            this.parent = parent;
        }

        /** A fresh loader for one run. */
        RunClassLoader newLoader() {
            return new RunClassLoader(this);
        }

        /** The platform's classes, and classes of the library and the simulator wherever they are found. */
        boolean isShared(String name) {
            if (name.startsWith("java.") || name.startsWith("javax.") || name.startsWith("jdk.") || name.startsWith("sun.")) {
                return true;
            }
            return sharedNames.computeIfAbsent(name, this::sharedByLocation);
        }

        /** The bytes of a resource in a jar, read the first time a run asks for it. */
        byte[] jarResource(URL url) throws IOException {
            try {
                return jarResources.computeIfAbsent(url.toString(), k -> {
                    try (InputStream in = ownConnection(url)) {
                        return in.readAllBytes();
                    } catch (IOException e) {
                        throw new UncheckedIOException(e);
                    }
                });
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
        }

        private boolean sharedByLocation(String name) {
            try {
                Class<?> parentCopy = Class.forName(name, false, parent);
                URL at = location(parentCopy);
                return at == null || shared.contains(at);
            } catch (ClassNotFoundException | LinkageError e) {
                return false;
            }
        }
    }

    /**
     * What a sweep's run loaders load: the class path of this process, and the folders or jars that hold
     * {@code classNames} (the robots, found through {@code parent}), less the simulator's own.
     */
    static Source source(List<String> classNames, ClassLoader parent) {
        Set<URL> shared = new LinkedHashSet<>();
        shared.add(location(RsClient.class));
        shared.add(location(RunClassLoader.class));
        Set<URL> urls = new LinkedHashSet<>();
        for (String name : classNames) {
            try {
                URL at = location(Class.forName(name, false, parent));
                if (at != null) {
                    urls.add(at);
                }
            } catch (ClassNotFoundException | LinkageError e) {
                // The run's server says so, naming dlcName.
            }
        }
        for (String entry : System.getProperty("java.class.path", "").split(File.pathSeparator)) {
            if (!entry.isEmpty()) {
                try {
                    urls.add(Paths.get(entry).toAbsolutePath().toUri().toURL());
                } catch (MalformedURLException | RuntimeException e) {
                    // Not a path: nothing to load from.
                }
            }
        }
        urls.removeAll(shared);
        shared.remove(null);
        return new Source(urls.toArray(new URL[0]), Set.copyOf(shared), parent);
    }

    /** Where a class was loaded from (its folder or jar), or null if that is unknown. */
    private static URL location(Class<?> type) {
        CodeSource source = type.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            return null;
        }
        try {
            return Path.of(source.getLocation().toURI()).toAbsolutePath().toUri().toURL();
        } catch (URISyntaxException | MalformedURLException | RuntimeException e) {
            return source.getLocation();
        }
    }

    /**
     * This run's copy of any class on its own class path; the Java platform's, the library's and the
     * simulator's, and anything it cannot find, from the sweep's loader.
     */
    @Override
    protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
        synchronized (getClassLoadingLock(name)) {
            Class<?> c = findLoadedClass(name);
            if (c == null && !source.isShared(name)) {
                try {
                    c = findClass(name);
                } catch (ClassNotFoundException e) {
                    c = null;
                }
            }
            if (c == null) {
                c = getParent().loadClass(name);
            }
            if (resolve) {
                resolveClass(c);
            }
            return c;
        }
    }

    /** The resource as a stream that no other run shares (see the class comment); null if there is none or it cannot be read. */
    @Override
    public InputStream getResourceAsStream(String name) {
        URL url = getResource(name);
        if (url == null) {
            return null;
        }
        try {
            if ("jar".equals(url.getProtocol())) {
                return new ByteArrayInputStream(source.jarResource(url));
            }
            InputStream in = ownConnection(url);
            synchronized (streams) {
                streams.put(in, null);
            }
            return in;
        } catch (IOException e) {
            return null;
        }
    }

    /** A stream of the resource on a connection of its own, not on the jar the JVM shares. */
    private static InputStream ownConnection(URL url) throws IOException {
        URLConnection connection = url.openConnection();
        connection.setUseCaches(false);
        return connection.getInputStream();
    }

    /** Closes the streams the run left open, then the loader's own jars. */
    @Override
    public void close() throws IOException {
        List<Closeable> open;
        synchronized (streams) {
            open = new ArrayList<>(streams.keySet());
            streams.clear();
        }
        for (Closeable c : open) {
            try {
                c.close();
            } catch (IOException e) {
                // Closing what the run left behind; the loader's own jars are closed all the same.
            }
        }
        super.close();
    }
}
