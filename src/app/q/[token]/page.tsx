import { ParticipantForm } from "@/features/questionnaires/participant-form";

// The participant's page: reached by a one-time link, never by an account.
export default async function Page({ params }: { params: Promise<{ token: string }> }) {
  const { token } = await params;
  return (
    <main className="mx-auto max-w-3xl px-4 py-8">
      <ParticipantForm token={token} />
    </main>
  );
}
