package rp1.io;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;

/**
 * Why a file operation failed, in words a user can act on. The file system's exceptions carry the
 * path and often nothing else ({@code NoSuchFileException: runs/x.txt}), so a message built from
 * {@code getMessage()} named the file twice and never said what was wrong with it.
 */
public final class IoFailures {
    private IoFailures() {
    }

    /**
     * What went wrong: "no such file or folder", "permission denied", ... for the file system's own
     * exceptions (naming the other file when there are two), else the exception's message.
     */
    public static String why(IOException e) {
        String other = e instanceof FileSystemException f && f.getOtherFile() != null ? " (" + f.getOtherFile() + ")" : "";
        if (e instanceof NoSuchFileException) {
            return "no such file or folder" + other;
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied" + other;
        }
        if (e instanceof FileAlreadyExistsException) {
            return "a file of that name is in the way" + other;
        }
        if (e instanceof NotDirectoryException) {
            return "not a folder" + other;
        }
        if (e instanceof DirectoryNotEmptyException) {
            return "the folder is not empty" + other;
        }
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return f.getReason() + other;
        }
        return e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
    }
}
