package rp1.simulator.batch;

import java.io.ByteArrayInputStream;
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
import java.security.CodeSigner;
import java.security.CodeSource;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.jar.JarFile;
import java.util.jar.Manifest;

import rp1.rossum.RsClient;

/**
 * The class loader of one run's robot ({@code --isolation loader}): the robot's classes, and every
 * class of the class path that is not the simulator's or the client library's, are loaded afresh
 * for each run, so a static field of the robot starts anew in every run, as it would in a process
 * of its own. The library ({@code rp1.rossum}) and the simulator come from the sweep's loader: the
 * server and the robot must agree on {@code RsClient}. A class the run's loader cannot find on the
 * class path is the sweep loader's.
 *
 * <p>The robot's classes and resources are found and read once per sweep ({@link Source}), and each
 * run defines its classes from those bytes and reads its resources from them: every run opening the
 * robot's jar, looking its entries up and inflating them again was about a twentieth of what the runs
 * of a 64-run sweep ran. The classes are defined as {@link URLClassLoader} would define them (code
 * source, package with the jar's manifest), without signers.
 *
 * <p>Nothing a run reads is read through the jar the whole JVM shares either: {@link URLClassLoader}
 * reads a resource stream through it and closes it when the loader is closed, so one run ending
 * pulled the jar from under another run reading its {@code rossum.ini}, and that run failed
 * ({@code ZipFile closed}, or a {@code NullPointerException} inside {@code JarURLConnection}) or its
 * robot quietly went on without its settings.
 */
final class RunClassLoader extends URLClassLoader {
    static {
        registerAsParallelCapable();
    }

    private final Source source;

    private RunClassLoader(Source source) {
        super("rp1-run", source.urls, source.parent);
        this.source = source;
    }

    /**
     * What the loaders of a sweep's runs have in common, worked out once for all of them: the folders
     * and jars they load from, which class names are the sweep's to share, and the robot's classes and
     * resources as found and read there (a jar or a class folder does not change while a sweep runs). A
     * run's robot resolves dozens of the library's names; working out where each one comes from anew
     * (its code source made into a URL) was a twentieth of a warm sweep's processor time.
     */
    static final class Source {
        /** More classes than this on the runs' class path are not looked through for static state. */
        private static final int MAX_CLASSES_LOOKED_THROUGH = 2000;
        private final URL[] urls;
        /** The robots' classes (dlcName). */
        private final List<String> roots;
        private final Set<URL> shared;
        private final ClassLoader parent;
        private final Map<String, Boolean> sharedNames = new ConcurrentHashMap<>();
        /**
         * Finds the robot's own classes and resources: the runs' class path, no parent. Open as long as
         * the sweep's runs may ask; its jars are closed when it is collected.
         */
        private final URLClassLoader finder;
        /** Where each name asked for was found on the runs' class path (empty: nowhere). */
        private final Map<String, Optional<URL>> found = new ConcurrentHashMap<>();
        /** The contents of each resource read so far, by URL. */
        private final Map<String, byte[]> contents = new ConcurrentHashMap<>();
        /** Each folder or jar of the runs' class path as a code source, with its jar's manifest. */
        private final Map<URL, Location> locations = new ConcurrentHashMap<>();

        /** A folder or jar classes are defined from. */
        private record Location(CodeSource codeSource, Manifest manifest) {
        }

        private Source(URL[] urls, Set<URL> shared, ClassLoader parent, List<String> roots) {
            this.roots = List.copyOf(roots);
            this.urls = urls;
            this.shared = shared;
            this.parent = parent;
            this.finder = new URLClassLoader(urls, null);
        }

        /** A fresh loader for one run. */
        RunClassLoader newLoader() {
            return new RunClassLoader(this);
        }

        /**
         * The first static field among the classes the runs' loaders load that can keep state (see
         * {@link StaticState}), as "CLASS.FIELD" or a reason; empty if none can.
         */
        Optional<String> staticState() {
            return StaticState.find(List.of(urls), MAX_CLASSES_LOOKED_THROUGH);
        }

        /**
         * Where the robot's code ends the process ({@link StaticState.Calls}): the robots' classes are
         * read, then every class of the runs' class path that they refer to, and so on, as "CLASS.METHOD
         * calls System.exit"; empty if none does, or if more classes than a sweep looks through are
         * reached. Only what a robot can reach counts: a class path often holds other programs too.
         */
        Optional<String> exitCall() {
            Deque<String> todo = new ArrayDeque<>(roots);
            Set<String> seen = new HashSet<>(roots);
            for (int looked = 0; !todo.isEmpty() && looked < MAX_CLASSES_LOOKED_THROUGH; looked++) {
                URL at = find(todo.pop().replace('.', '/') + ".class");
                if (at == null) {
                    continue; // the library's, the simulator's or the platform's
                }
                try {
                    StaticState.Calls calls = StaticState.calls(contents(at));
                    if (calls.exit().isPresent()) {
                        return calls.exit();
                    }
                    for (String name : calls.classes()) {
                        if (seen.add(name)) {
                            todo.add(name);
                        }
                    }
                } catch (IOException | RuntimeException e) {
                    // A class file that cannot be read fails its run when it is loaded, which says why.
                }
            }
            return Optional.empty();
        }

        /** The platform's classes, and classes of the library and the simulator wherever they are found. */
        boolean isShared(String name) {
            if (name.startsWith("java.") || name.startsWith("javax.") || name.startsWith("jdk.") || name.startsWith("sun.")) {
                return true;
            }
            return sharedNames.computeIfAbsent(name, this::sharedByLocation);
        }

        /** Where {@code name} is on the runs' class path, or null. */
        URL find(String name) {
            return found.computeIfAbsent(name, n -> Optional.ofNullable(finder.findResource(n))).orElse(null);
        }

        /** The contents of the resource at {@code url}, read the first time a run asks for it. */
        byte[] contents(URL url) throws IOException {
            try {
                return contents.computeIfAbsent(url.toString(), k -> {
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

        /** The folder or jar of the runs' class path that {@code resource} (found there) is in. */
        Location locationOf(URL resource) throws IOException {
            String at = resource.toString();
            for (URL u : urls) {
                String base = u.toString();
                if (at.startsWith("jar:" + base + "!/") || at.startsWith(base)) {
                    return locations.computeIfAbsent(u, Source::open);
                }
            }
            throw new IOException(resource + " is not on the runs' class path");
        }

        /** The folder or jar as a code source, with the jar's manifest if it has one that can be read. */
        private static Location open(URL u) {
            Manifest manifest = null;
            if (!u.getPath().endsWith("/")) {
                try (JarFile jar = new JarFile(new File(u.toURI()))) {
                    manifest = jar.getManifest();
                } catch (IOException | URISyntaxException | IllegalArgumentException e) {
                    // Not a readable jar on a file system: its classes' bytes were read all the same,
                    // so they are defined without its manifest.
                }
            }
            return new Location(new CodeSource(u, (CodeSigner[]) null), manifest);
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
        return new Source(urls.toArray(new URL[0]), Set.copyOf(shared), parent, classNames);
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

    /** The robot's class, from the bytes the sweep read (see the class comment). */
    @Override
    protected Class<?> findClass(String name) throws ClassNotFoundException {
        URL url = source.find(name.replace('.', '/').concat(".class"));
        if (url == null) {
            throw new ClassNotFoundException(name);
        }
        try {
            byte[] bytes = source.contents(url);
            Source.Location at = source.locationOf(url);
            int dot = name.lastIndexOf('.');
            if (dot > 0) {
                definePackageOnce(name.substring(0, dot), at);
            }
            return defineClass(name, bytes, 0, bytes.length, at.codeSource());
        } catch (IOException e) {
            throw new ClassNotFoundException(name, e);
        }
    }

    /** Defines the package, with the jar's manifest if there is one, unless it already is. */
    private void definePackageOnce(String pkg, Source.Location at) {
        if (getDefinedPackage(pkg) != null) {
            return;
        }
        try {
            if (at.manifest() != null) {
                definePackage(pkg, at.manifest(), at.codeSource().getLocation());
            } else {
                definePackage(pkg, null, null, null, null, null, null, null);
            }
        } catch (IllegalArgumentException e) {
            // Defined meanwhile by another thread of the run.
        }
    }

    /** Where the resource is on the runs' class path, as the sweep found it once. */
    @Override
    public URL findResource(String name) {
        return source.find(name);
    }

    /** The resource from the bytes the sweep read (see the class comment); null if there is none or it cannot be read. */
    @Override
    public InputStream getResourceAsStream(String name) {
        URL url = getResource(name);
        if (url == null) {
            return null;
        }
        try {
            return new ByteArrayInputStream(source.contents(url));
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
}
