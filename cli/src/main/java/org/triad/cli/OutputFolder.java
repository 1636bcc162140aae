package org.triad.cli;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A folder a command writes into, made ready before the command does any work, so that one it
 * cannot use is refused at once (exit 2) with the path and the cause.
 */
final class OutputFolder {
	private OutputFolder() {
	}

	/** Creates the folder if needed and proves it writable by writing into it; a problem is a {@link ModelSession.UserError}. */
	static Path prepare(Path dir, String option) {
		String what = option + " " + dir;
		if (Files.exists(dir) && !Files.isDirectory(dir)) {
			throw new ModelSession.UserError(what + ": not a folder (a file of that name exists)");
		}
		try {
			Files.createDirectories(dir);
		} catch (FileAlreadyExistsException e) {
			throw new ModelSession.UserError(what + ": cannot create the folder: " + e.getFile() + " exists and is not a folder");
		} catch (AccessDeniedException e) {
			throw new ModelSession.UserError(what + ": cannot create the folder: permission denied for " + e.getFile());
		} catch (IOException e) {
			throw new ModelSession.UserError(what + ": cannot create the folder: " + reason(e));
		}
		try {
			Files.delete(Files.createTempFile(dir, ".triad-", ".probe"));
		} catch (AccessDeniedException e) {
			throw new ModelSession.UserError(what + ": cannot write into the folder: permission denied");
		} catch (IOException e) {
			throw new ModelSession.UserError(what + ": cannot write into the folder: " + reason(e));
		}
		return dir;
	}

	private static String reason(IOException e) {
		if (e instanceof FileSystemException f && f.getReason() != null) {
			return f.getReason();
		}
		return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
	}
}
