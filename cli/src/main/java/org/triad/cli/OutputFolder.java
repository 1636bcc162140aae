package org.triad.cli;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A folder a command writes into, checked before the command does any work, so that one it cannot
 * use is refused at once (exit 2) with the path and the cause. Nothing is created: a command that
 * stops early (model errors) leaves no empty folder behind.
 */
final class OutputFolder {
	private OutputFolder() {
	}

	/**
	 * Checks that the folder exists and takes files, or can be created: its nearest existing ancestor is
	 * a folder that takes files. A problem is a {@link ModelSession.UserError}.
	 */
	static Path check(Path dir, String option) {
		String what = option + " " + dir;
		Path existing = dir.toAbsolutePath().normalize();
		while (!Files.exists(existing)) {
			existing = existing.getParent();
			if (existing == null) {
				throw new ModelSession.UserError(what + ": cannot create the folder: no existing parent");
			}
		}
		boolean self = existing.equals(dir.toAbsolutePath().normalize());
		if (!Files.isDirectory(existing)) {
			throw new ModelSession.UserError(what + (self ? ": not a folder (a file of that name exists)"
					: ": cannot create the folder: " + existing + " exists and is not a folder"));
		}
		try {
			Files.delete(Files.createTempFile(existing, ".triad-", ".probe"));
		} catch (AccessDeniedException e) {
			throw new ModelSession.UserError(what + ": " + (self ? "cannot write into the folder" : "cannot create the folder in " + existing)
					+ ": permission denied");
		} catch (IOException e) {
			throw new ModelSession.UserError(what + ": " + (self ? "cannot write into the folder" : "cannot create the folder in " + existing)
					+ ": " + reason(e));
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
